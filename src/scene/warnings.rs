//! Keys that parse but change nothing: a setting of a technique the scene's
//! path does not run, a light's key its type ignores, a camera's key its
//! projection ignores. Each is legal (the demo switches paths and types, and
//! "save as" writes every render knob), so it is a warning, not an error;
//! `gloss render`, `plan`, `bench` and the demo print them at start-up.
//!
//! A key is reported only when the file (or `--set`) wrote it, and, where
//! the key has a default, only when its value differs from the default: the
//! default is what "no effect" looks like anyway, and "save as" writes it.

use super::{
    Accumulation, AlphaTest, BillboardMode, CubeRender, DeferredLights, Falloff, LightKind,
    MirrorOrder, Projection, RenderPath, Scene, Shading, ShadowFit,
};

impl Scene {
    /// What the scene sets to no effect, one line per key, each starting
    /// with the key (`render.cutoff = 0.01 has no effect on the forward
    /// path: ...`). Empty for a scene whose every key counts.
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        self.render_warnings(&mut w);
        self.light_warnings(&mut w);
        self.material_warnings(&mut w);
        self.camera_warnings(&mut w);
        self.skybox_warnings(&mut w);
        w.extend(self.file_warnings.iter().cloned());
        w.extend(super::area_lights::warnings(self));
        if self.tessellation.is_some() && self.render.path != RenderPath::Forward {
            w.push(format!(
                "[tessellation] is not drawn on the {} path: the tessellated terrain is a forward-path pass (render.path = \"forward\" draws it)",
                self.render.path.name()
            ));
        }
        // What loading each skinned mesh's file said, once per file.
        let mut seen = Vec::new();
        for o in &self.objects {
            let said = match (&o.skin, &o.mesh) {
                (Some(s), _) => s.warnings.as_ref(),
                (None, super::MeshSource::GltfPart(p)) => p.warnings.as_ref(),
                _ => continue,
            };
            if !seen.iter().any(|p| std::ptr::eq(*p, said)) {
                seen.push(said);
                w.extend(said.iter().cloned());
            }
        }
        w
    }

    /// The warnings that hold on every render path (`gloss bench` runs the
    /// scene on several).
    pub fn warnings_on_every_path(&self) -> Vec<String> {
        let mut common = self.warnings();
        for &path in RenderPath::ALL {
            let mut s = self.clone();
            s.render.path = path;
            let there = s.warnings();
            common.retain(|w| there.contains(w));
        }
        common
    }

    /// Print `warnings` on stderr, "warning: FILE: ..." each.
    pub fn print_warnings(&self, warnings: &[String]) {
        for w in warnings {
            eprintln!("warning: {}: {w}", self.path.display());
        }
    }

    fn written(&self, key: &str) -> bool {
        self.keys_written.contains(key)
    }

    fn render_warnings(&self, w: &mut Vec<String>) {
        let r = &self.render;
        let path = r.path;
        let on_path = format!("has no effect on the {path} path");
        w.extend(super::ambient_occlusion::warning(r));
        w.extend(super::far_field::warning(self));
        let mut warn = |key: &str, set: bool, value: String, why: &str| {
            if set && self.written(&format!("render.{key}")) {
                w.push(format!("render.{key} = {value} {why}"));
            }
        };
        warn(
            "shading",
            path != RenderPath::Forward && r.shading != Shading::Phong,
            format!("\"{}\"", r.shading),
            &format!(
                "{on_path}: only the forward path shades per triangle or per vertex (the G-buffer paths light every pixel)"
            ),
        );
        warn(
            "cutoff",
            // The windowed falloff ends every light at its cutoff radius, on every path.
            matches!(path, RenderPath::Forward | RenderPath::Deferred)
                && r.falloff != super::Falloff::Windowed
                && r.cutoff != 5.0 / 256.0,
            r.cutoff.to_string(),
            &format!(
                "{on_path}: only light volumes (the volumes, prepass and tiled paths) end where a light falls to it"
            ),
        );
        warn(
            "stencil_volumes",
            path != RenderPath::Volumes && r.stencil_volumes,
            "true".into(),
            &format!(
                "{on_path}: the stencil test marks light volumes, which only the volumes path draws"
            ),
        );
        warn(
            "accumulation",
            path == RenderPath::Forward && r.accumulation != Accumulation::Rgba16f,
            format!("\"{}\"", r.accumulation),
            &format!("{on_path}: it has no light accumulation target (the deferred paths have)"),
        );
        warn(
            "deferred_lights",
            path != RenderPath::Deferred && r.deferred_lights != DeferredLights::PerLight,
            format!("\"{}\"", r.deferred_lights),
            &format!(
                "{on_path}: only the full-screen deferred path loops over the lights (the volumes and prepass paths draw a volume per light)"
            ),
        );
        for (key, set, value) in [
            ("tile_size", r.tile_size != 16, r.tile_size.to_string()),
            (
                "depth_slices",
                r.depth_slices != 16,
                r.depth_slices.to_string(),
            ),
            ("far_field", r.far_field != 0, r.far_field.to_string()),
            ("far_field_sh", r.far_field_sh, r.far_field_sh.to_string()),
            (
                "near_radius",
                r.near_radius != 1.0,
                r.near_radius.to_string(),
            ),
        ] {
            warn(
                key,
                path != RenderPath::Tiled && set,
                value,
                &format!("{on_path}: only the tiled path bins lights into tiles and slices"),
            );
        }
        warn(
            "msaa",
            path != RenderPath::Forward && r.msaa > 1,
            r.msaa.to_string(),
            &format!(
                "{on_path}: MSAA is on the forward path only (a [[post]] fxaa pass anti-aliases every path)"
            ),
        );
        let no_mirror = "has no effect: no object is a mirror";
        let mirrors = self.objects.iter().any(|o| o.mirror.is_some());
        for (key, set, value) in [
            (
                "mirror_order",
                r.mirror_order != MirrorOrder::NormalFirst,
                format!("\"{}\"", r.mirror_order),
            ),
            (
                "mirror_depth",
                r.mirror_depth != 1,
                r.mirror_depth.to_string(),
            ),
            ("mirror_clip", !r.mirror_clip, "false".into()),
            ("mirror_winding", !r.mirror_winding, "false".into()),
        ] {
            warn(key, !mirrors && set, value, no_mirror);
        }
        let billboards = !self.billboards.is_empty();
        warn(
            "billboards",
            !billboards && r.billboards != BillboardMode::AlphaTest,
            format!("\"{}\"", r.billboards),
            "has no effect: the scene has no billboards",
        );
        warn(
            "billboard_alpha_ref",
            r.billboard_alpha_ref != 0.5 && !billboards,
            r.billboard_alpha_ref.to_string(),
            "has no effect: the scene has no billboards",
        );
        warn(
            "billboard_alpha_ref",
            r.billboard_alpha_ref != 0.5 && billboards && r.billboards != BillboardMode::AlphaTest,
            r.billboard_alpha_ref.to_string(),
            &format!(
                "has no effect with render.billboards = \"{}\": only the alpha test compares with it",
                r.billboards
            ),
        );
        let no_outlines = "has no effect: the scene has no [outlines]";
        warn(
            "outlines",
            self.outlines.is_none() && !r.outlines,
            "false".into(),
            no_outlines,
        );
        let width = r.outline_width.to_string();
        warn(
            "outline_width",
            self.outlines.is_none() && r.outline_width != 4,
            width,
            no_outlines,
        );
        let no_field = "has no effect: the scene has no [instancing] field";
        warn(
            "instancing",
            self.instancing.is_none() && !r.instancing,
            "false".into(),
            no_field,
        );
        let transparent =
            (self.objects.iter()).any(|o| self.materials[o.material].is_transparent());
        warn(
            "sort_transparent",
            !transparent && !r.sort_transparent,
            "false".into(),
            "has no effect: no object's material has opacity < 1",
        );
        warn(
            "transparency",
            !transparent && r.transparency != super::settings::Transparency::Sorted,
            format!("\"{}\"", r.transparency),
            "has no effect: no object's material has opacity < 1",
        );
        warn(
            "sort_transparent",
            transparent
                && !r.sort_transparent
                && r.transparency != super::settings::Transparency::Sorted,
            "false".into(),
            &format!(
                "has no effect with render.transparency = \"{}\": only the sorted pass sorts",
                r.transparency
            ),
        );
        warn(
            "peel_layers",
            r.peel_layers != 8 && r.transparency != super::settings::Transparency::DepthPeeling,
            r.peel_layers.to_string(),
            "has no effect: only render.transparency = \"depth_peeling\" peels layers",
        );
        warn(
            "post_chain",
            self.post.is_empty() && r.post_chain != super::post::ChainForm::PingPong,
            format!("\"{}\"", r.post_chain),
            "has no effect: the scene has no [[post]] passes",
        );
    }

    fn light_warnings(&self, w: &mut Vec<String>) {
        let listed = self.lights.len() - self.grid_lights.unwrap_or(0);
        for (i, l) in self.lights[..listed].iter().enumerate() {
            let kind = match l.kind {
                LightKind::Directional => "directional",
                LightKind::Point => "point",
                LightKind::Spot => "spot",
            };
            let mut warn = |key: &str, ignored: bool, why: &str| {
                let key = format!("lights[{i}].{key}");
                if ignored && self.written(&key) {
                    w.push(format!("{key} has no effect on a {kind} light: {why}"));
                }
            };
            let directional = l.kind == LightKind::Directional;
            warn(
                "direction",
                l.kind == LightKind::Point,
                "a point light shines every way",
            );
            warn(
                "position",
                directional,
                "a directional light is infinitely far away (only its direction counts)",
            );
            warn(
                "attenuation",
                directional,
                "a directional light is not attenuated",
            );
            for angle in ["inner_angle", "outer_angle"] {
                warn(
                    angle,
                    l.kind != LightKind::Spot,
                    "only a spot light has a cone",
                );
            }
            warn(
                "range",
                directional,
                "a directional light is not attenuated",
            );
            let shadow = l.shadow.as_ref();
            warn(
                "shadow.cube",
                shadow.is_some_and(|s| s.cube != CubeRender::SixPasses)
                    && l.kind != LightKind::Point,
                "only a point light's shadow map is a cube",
            );
            warn(
                "shadow.fit",
                shadow.is_some_and(|s| s.fit != ShadowFit::Visible) && !directional,
                "only a directional light's shadow box is fitted (spot and point lights see from their position)",
            );
            let range = format!("lights[{i}].range");
            if !directional && self.render.falloff != Falloff::Linear && self.written(&range) {
                w.push(format!(
                    "{range} has no effect with render.falloff = \"{}\": only the linear falloff, 1 - d / range, reads it",
                    self.render.falloff
                ));
            }
        }
    }

    fn material_warnings(&self, w: &mut Vec<String>) {
        for (index, m) in self.materials.iter().enumerate().skip(1) {
            let key = format!("materials.{}", m.name);
            let fixed = matches!(m.alpha_test, AlphaTest::Always | AlphaTest::Never);
            if fixed && m.alpha_ref != 0.5 && self.written(&format!("{key}.alpha_ref")) {
                w.push(format!(
                    "{key}.alpha_ref = {} has no effect with alpha_test = \"{}\": that test compares with nothing",
                    m.alpha_ref, m.alpha_test
                ));
            }
            if !self.objects.iter().any(|o| o.material == index) {
                w.push(format!("{key} has no effect: no object uses it"));
            }
            w.extend(self.parallax_warning(&key, m));
        }
        // Parallax mapping (lighting/parallax_mapping.rs) with no height map.
        let relief = self.materials.iter().any(|m| m.height_map.is_some());
        let r = &self.render;
        for (key, set) in [
            ("parallax", r.parallax != super::Parallax::Occlusion),
            ("parallax_layers", r.parallax_layers != 32),
            ("parallax_shadows", !r.parallax_shadows),
            ("parallax_uv", r.parallax_uv),
        ] {
            let key = format!("render.{key}");
            if !relief && set && self.written(&key) {
                w.push(format!("{key} has no effect: no material has a height_map"));
            }
        }
        // Exploding objects (vertex_geometry/exploding_objects.rs) run on one path.
        if r.explode && !r.explodes() {
            w.push(format!(
                "render.explode has no effect: exploding objects are drawn on the forward path with Phong shading; here ({} path, {} shading) the objects are drawn whole",
                r.path, r.shading
            ));
        }
    }

    /// A material with a height map that parallax mapping will not draw.
    fn parallax_warning(&self, key: &str, m: &super::Material) -> Option<String> {
        let r = &self.render;
        m.height_map.as_ref()?;
        if r.parallax == super::Parallax::Off {
            return None;
        }
        let why = if m.is_transparent() {
            "the transparency pass draws it (opacity < 1), without parallax".to_string()
        } else if r.path != RenderPath::Forward || r.shading != super::Shading::Phong {
            format!(
                "parallax mapping runs on the forward path with Phong shading; here ({} path, {} shading) it is drawn with its normal map only",
                r.path, r.shading
            )
        } else {
            return None;
        };
        Some(format!("{key}.height_map has no effect: {why}"))
    }

    fn camera_warnings(&self, w: &mut Vec<String>) {
        let views = self.views.iter().enumerate();
        let cameras = std::iter::once(("camera".to_string(), &self.camera)).chain(
            views.filter_map(|(i, v)| Some((format!("views[{i}].camera"), v.camera.as_ref()?))),
        );
        for (key, c) in cameras {
            w.extend(super::camera_limits::warning(c, &key));
            let (ignored, projection) = match c.projection {
                Projection::Perspective { .. } => ("half_height", "a perspective"),
                Projection::Orthographic { .. } => ("fov_y", "an orthographic"),
            };
            let key = format!("{key}.{ignored}");
            if self.written(&key) {
                let why = match ignored {
                    "fov_y" => "an orthographic camera's view box is half_height high",
                    _ => "a perspective camera's view widens with fov_y",
                };
                w.push(format!("{key} has no effect on {projection} camera: {why}"));
            }
        }
    }
}
