//! Nothing dropped in silence: a pass a path cannot run is a warning and a
//! plan line; a value past the world limit (1e9 scene units, MAX_EXTENT) is
//! refused in every newer input, naming the key.

use crate::{BASE, contains_all, gloss_in, temp_dir, write};

fn grey_png() -> Vec<u8> {
    let img = image::GrayImage::from_pixel(4, 4, image::Luma([128]));
    let mut bytes = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .unwrap();
    bytes
}

const TERRAIN: &str =
    "\n[tessellation]\nsize = 4.0\npatches = 2\nheight = 0.5\ndisplacement = \"bumps.png\"\n";

#[test]
fn the_tessellated_terrain_on_a_deferred_path_is_a_warning_and_a_plan_line() {
    let dir = temp_dir("tess_deferred");
    write(&dir, "bumps.png", grey_png());
    write(&dir, "scene.toml", format!("{BASE}{TERRAIN}"));
    for path in ["deferred", "volumes", "tiled"] {
        let set = format!("render.path={path}");
        let run = gloss_in(&dir, &["plan", "scene.toml", "--set", &set], &[]);
        contains_all(
            run.succeeded(),
            &[
                "warning: scene.toml: [tessellation] is not drawn on the",
                "forward-path pass",
            ],
        );
        contains_all(
            &run.stdout,
            &["not drawn: the [tessellation] terrain: its pass runs on the forward path only"],
        );
        let run = gloss_in(
            &dir,
            &["render", "scene.toml", "--set", &set, "-o", "out.png"],
            &["out.png"],
        );
        contains_all(run.succeeded(), &["[tessellation] is not drawn"]);
    }
    // On the forward path it is drawn: no warning, a pass, no such line.
    let run = gloss_in(&dir, &["plan", "scene.toml"], &[]);
    assert!(!run.succeeded().contains("tessellation"), "{}", run.stderr);
    assert!(!run.stdout.contains("not drawn"));
    assert!(run.stdout.contains("tessellation"));
}

#[test]
fn values_past_the_world_limit_are_refused_in_every_newer_input() {
    let dir = temp_dir("world_limit");
    write(&dir, "bumps.png", grey_png());
    write(&dir, "sprite.png", grey_png());
    let particles = "\n[particles]\nemitter = [0.0, 0.0, 0.0]\nsize = 0.1\nspeed = 1.0\n";
    let billboard =
        "\n[[billboards]]\ncenter = [0.0, 1.0, 0.0]\nsize = [1.0, 1.0]\nsprite = \"sprite.png\"\n";
    let animation = "\n[[animation.tracks]]\nobject = \"floor\"\ntimes = [0.0, 1.0]\nposition = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]\nscale = [[1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]\n";
    let cases: &[(&str, &str, &str, &str)] = &[
        (
            particles,
            "emitter = [0.0, 0.0, 0.0]",
            "emitter = [2e9, 0.0, 0.0]",
            "particles.emitter",
        ),
        (particles, "size = 0.1", "size = 3e9", "particles.size"),
        (particles, "speed = 1.0", "speed = 1e10", "particles.speed"),
        (TERRAIN, "size = 4.0", "size = 2e9", "tessellation.size"),
        (
            TERRAIN,
            "height = 0.5",
            "height = -5e9",
            "tessellation.height",
        ),
        (
            billboard,
            "center = [0.0, 1.0, 0.0]",
            "center = [0.0, 1.0, 1e12]",
            "billboards[0].center",
        ),
        (
            billboard,
            "size = [1.0, 1.0]",
            "size = [1.0, 2e9]",
            "billboards[0].size",
        ),
        (
            animation,
            "[1.0, 0.0, 0.0]]",
            "[1e10, 0.0, 0.0]]",
            "animation.tracks[0].position[1]",
        ),
        (
            animation,
            "[2.0, 2.0, 2.0]]",
            "[2.0, 5e9, 2.0]]",
            "animation.tracks[0].scale[1]",
        ),
    ];
    for (i, (section, from, to, key)) in cases.iter().enumerate() {
        assert_eq!(section.matches(from).count(), 1, "{from}");
        let name = format!("case{i}.toml");
        // The section at its ordinary value is read.
        write(&dir, &name, format!("{BASE}{section}"));
        gloss_in(&dir, &["plan", &name], &[]).succeeded();
        write(&dir, &name, format!("{BASE}{}", section.replace(from, to)));
        for command in ["plan", "render"] {
            let mut args = vec![command, name.as_str()];
            if command == "render" {
                args.extend(["-o", "out.png"]);
            }
            let run = gloss_in(&dir, &args, &[]);
            contains_all(
                run.failed(),
                &[&name, &format!("{key}: "), "is past 1e9 scene units"],
            );
        }
    }
}
