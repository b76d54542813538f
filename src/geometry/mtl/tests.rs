use super::*;

#[test]
fn options_are_split_from_the_file_name() {
    let (f, bm, ign) = texture_options("-bm 0.5 my normals.png");
    assert_eq!(
        (f.as_str(), bm, ign.len()),
        ("my normals.png", Some(0.5), 0)
    );
    let (f, bm, ign) = texture_options("-s 2 2 1 -o 0.5 -clamp on tex\\a b.jpg");
    assert_eq!((f.as_str(), bm), ("tex\\a b.jpg", None));
    assert_eq!(ign, vec!["-s 2 2 1", "-o 0.5", "-clamp on"]);
    let (f, _, _) = texture_options("plain.png");
    assert_eq!(f, "plain.png");
}

#[test]
fn mapping_follows_the_documented_rules() {
    let dir = std::env::temp_dir().join(format!("gloss-mtl-unit-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("Tex")).unwrap();
    std::fs::write(dir.join("Tex/Body Diffuse.PNG"), b"x").unwrap();
    let text = "newmtl a\nKd 0.2 0.4 2\nKs 0.5 0.5 0.5\nNs 0\nTr 0.25\nillum 1\n\
                map_Kd tex\\body diffuse.png\nnorm -bm 2 missing.png\n\
                newmtl b\nd 0.5\nmap_kd Tex/Body Diffuse.PNG\n";
    let (m, w) = parse_mtl(text.as_bytes(), &dir.join("x.mtl")).unwrap();
    assert_eq!(m.len(), 2);
    assert_eq!(m[0].diffuse, [0.2, 0.4, 1.0]);
    assert_eq!(m[0].specular, [0.0; 3], "illum 1 has no highlight");
    assert_eq!(m[0].shininess, 1.0);
    assert_eq!(m[0].opacity, 0.75);
    assert_eq!(
        m[0].diffuse_map.as_deref(),
        Some(dir.join("Tex/Body Diffuse.PNG").as_path())
    );
    assert_eq!(m[0].normal_map, None);
    assert!(
        w.iter()
            .any(|w| w.contains("\"a\"") && w.contains("missing.png")),
        "{w:?}"
    );
    assert!(
        w.iter().any(|w| w.contains("Kd") && w.contains("clamped")),
        "{w:?}"
    );
    assert_eq!(m[1].opacity, 0.5);
    assert_eq!(
        m[1].diffuse, [1.0; 3],
        "map_Kd alone shows the texture as it is"
    );
    assert!(m[1].diffuse_map.is_some(), "map_kd in another case");
}

#[test]
fn malformed_lines_are_named() {
    let p = Path::new("bad.mtl");
    let e = parse_mtl(b"newmtl a\nKd 1 x 0\n", p)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("bad.mtl") && e.contains("line 2") && e.contains("Kd 1 x 0"),
        "{e}"
    );
    let e = parse_mtl(&[0xff, 0xfe], p).unwrap_err().to_string();
    assert!(e.contains("not UTF-8"), "{e}");
    // tobj panics on these (a colour of fewer than three numbers).
    for bad in ["Kd", "Kd 0.5 0.5", "Ks  1\t2 "] {
        let e = parse_mtl(format!("newmtl a\n{bad}\n").as_bytes(), p)
            .unwrap_err()
            .to_string();
        assert!(e.contains("line 2") && e.contains("three numbers"), "{e}");
    }
    // One number is grey (the MTL specification).
    let (m, _) = parse_mtl(b"newmtl a\nKd 0.25\n", p).unwrap();
    assert_eq!(m[0].diffuse, [0.25; 3]);
}
