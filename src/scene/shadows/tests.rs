//! The `shadow` table's parsing and saving.

use super::*;

fn parse(text: &str) -> Result<Option<Shadow>> {
    let t: toml::Table = toml::from_str(text).map_err(|e| anyhow::anyhow!("{e}"))?;
    shadow("lights[0].shadow", t.get("shadow"), false)
}

#[test]
fn true_false_and_a_table() {
    assert_eq!(parse("shadow = false").unwrap(), None);
    assert_eq!(parse("shadow = true").unwrap(), Some(Shadow::default()));
    let s = parse("shadow = { resolution = 512, pcf = \"5x5\", cull_front = true }")
        .unwrap()
        .unwrap();
    assert_eq!((s.resolution, s.pcf, s.cull_front), (512, Pcf::Box5, true));
    assert_eq!(s.bias, Shadow::default().bias);
}

#[test]
fn bad_values_name_their_key() {
    for (text, key) in [
        (
            "shadow = { resolution = 1000 }",
            "lights[0].shadow.resolution",
        ),
        ("shadow = { bias = -1.0 }", "lights[0].shadow.bias"),
        (
            "shadow = { slope_bias = nan }",
            "lights[0].shadow.slope_bias",
        ),
        ("shadow = { pcf = \"7x7\" }", "lights[0].shadow.pcf"),
        ("shadow = { fit = \"tight\" }", "lights[0].shadow.fit"),
        ("shadow = { cube = \"one\" }", "lights[0].shadow.cube"),
        ("shadow = { cascades = 9 }", "lights[0].shadow.cascades"),
        ("shadow = { cascades = 0 }", "lights[0].shadow.cascades"),
        ("shadow = { split = \"log\" }", "lights[0].shadow.split"),
        ("shadow = { lambda = 1.5 }", "lights[0].shadow.lambda"),
        ("shadow = { lambda = nan }", "lights[0].shadow.lambda"),
        ("shadow = { blend = 0.75 }", "lights[0].shadow.blend"),
        (
            "shadow = { size = 512 }",
            "lights[0].shadow: unknown field `size`",
        ),
        (
            "shadow = 1",
            "lights[0].shadow: expected true, false or a table",
        ),
    ] {
        let e = parse(text).unwrap_err().to_string();
        assert!(e.contains(key), "{text}: {e}");
    }
}

#[test]
fn the_saved_table_reads_back_the_same() {
    let s = Shadow {
        resolution: 256,
        bias: 0.25,
        slope_bias: 3.0,
        normal_offset: 0.5,
        cull_front: true,
        pcf: Pcf::Poisson,
        fit: ShadowFit::Scene,
        cube: CubeRender::GeometryShader,
        cascades: 4,
        split: CascadeSplit::Logarithmic,
        lambda: 0.25,
        stable: false,
        blend: 0.2,
        cascade_colors: true,
    };
    let text = format!("shadow = {}", toml::Value::Table(shadow_table(&s)));
    assert_eq!(parse(&text).unwrap(), Some(s));
}
