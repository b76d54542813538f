//! Carrying out what the panel and the keys ask: loading a scene (the old
//! one keeps running when the new one fails), new render settings, a new
//! light count, the inspector's view, screenshots; and reloading the scene
//! file or the shaders when they change on disk.

use super::keys::KeyAction;
use super::panel::Action;
use super::shaders::shader_names;
use super::{Demo, compare, modified};
use crate::assets;
use crate::renderer::Renderer;
use crate::scene::{Light, RenderPath, Scene, Shading, validate_attenuation};
use anyhow::{Result, anyhow, bail};
use std::path::Path;
use std::time::{Duration, Instant};

impl Demo {
    pub(super) fn apply(&mut self, action: Action) {
        // A comparison holds while the frame it compared stays the same.
        if matches!(
            action,
            Action::Load(_)
                | Action::Reload
                | Action::Settings(_)
                | Action::LightCount(_)
                | Action::LightGrid(_)
                | Action::Views(_)
                | Action::Billboards(..)
                | Action::Lights(_)
                | Action::Materials(_)
                | Action::Objects(_)
                | Action::Post(_)
        ) && let Some(run) = self.running.as_mut()
        {
            run.comparison = None;
        }
        let result = match action {
            Action::Load(path) => self.load(&assets::scene_path(&path)),
            Action::Reload => self.load(&self.scene_path.clone()),
            Action::SaveAs(path) => {
                // The saved scene looks from where the demo looks now.
                let mut scene = self.scene.clone();
                scene.camera = self.orbit.camera();
                scene.save_as(&path)
            }
            .map(|()| {
                println!("gloss: saved {}", path.display());
                self.status = Some(format!("saved {}", path.display()));
            }),
            Action::Settings(s) => {
                let mut scene = self.scene.clone();
                scene.render = s;
                self.set_values(scene)
            }
            Action::Lights(lights) => checked(lights).and_then(|lights| {
                let mut scene = self.scene.clone();
                scene.lights = lights;
                self.set_values(scene)
            }),
            Action::Materials(materials) => {
                // A new texture must be loaded, and new sampling needs its
                // sampler objects and uv transform: a new renderer.
                let textures = |m: &[crate::scene::Material]| -> Vec<_> {
                    m.iter()
                        .map(|m| (m.diffuse_texture.clone(), m.texturing))
                        .collect()
                };
                let reload = textures(&materials) != textures(&self.scene.materials);
                let mut scene = self.scene.clone();
                scene.materials = materials;
                if reload {
                    self.rebuild(&scene).map(|()| self.scene = scene)
                } else {
                    self.set_values(scene)
                }
            }
            Action::Billboards(list, fields) => {
                // Their number may change: a new renderer (instance buffer).
                let mut scene = self.scene.clone();
                scene
                    .set_billboards(list, fields)
                    .and_then(|()| self.rebuild(&scene).map(|()| self.scene = scene))
            }
            Action::Views(views) => views
                .iter()
                .enumerate()
                .try_for_each(|(i, v)| crate::scene::check_viewport(i, v.viewport))
                .and_then(|()| {
                    let mut scene = self.scene.clone();
                    scene.views = views;
                    self.set_values(scene)
                }),
            Action::LightGrid(grid) => {
                let mut scene = self.scene.clone();
                scene
                    .set_light_grid(grid)
                    .and_then(|()| self.set_values(scene))
            }
            Action::LightCount(n) => {
                let mut scene = self.scene.clone();
                scene
                    .set_light_count(n)
                    .and_then(|()| self.rebuild(&scene).map(|()| self.scene = scene))
            }
            Action::Inspect(view) => {
                if let Some(run) = self.running.as_mut() {
                    run.panel.inspect = view;
                    run.inspected = None;
                }
                Ok(())
            }
            Action::Screenshot(with_panel) => {
                if let Some(run) = self.running.as_mut() {
                    run.screenshot = Some(with_panel);
                }
                Ok(())
            }
            Action::Compare => match self.running.as_mut() {
                Some(run) => compare::compare(
                    &run.ctx.gl,
                    &run.ctx.debug,
                    &self.sources,
                    &run.renderer,
                    &self.orbit.camera(),
                )
                .map(|c| {
                    self.status = Some(format!("{}: {}", c.what, c.metrics));
                    run.comparison = Some(c);
                }),
                None => Ok(()),
            },
            Action::Objects(mut objects) => {
                // A new mesh, material or parent changes what is uploaded
                // and drawn with what: a new renderer. Transforms only: new values.
                let structure = |o: &crate::scene::Object| (o.mesh.clone(), o.material, o.parent);
                let rebuild =
                    (objects.iter().map(structure)).ne(self.scene.objects.iter().map(structure));
                no_parent_cycle(&objects).and_then(|()| {
                    crate::scene::update_models(&mut objects);
                    let mut scene = self.scene.clone();
                    scene.objects = objects;
                    if rebuild {
                        self.rebuild(&scene).map(|()| self.scene = scene)
                    } else {
                        self.set_values(scene)
                    }
                })
            }
            Action::Post(chain) => {
                super::post_chain::checked(&self.scene, &chain).and_then(|s| self.set_values(s))
            }
            Action::Camera(c) => {
                self.orbit.set_lens(&c);
                self.scene.camera = c;
                Ok(())
            }
            Action::Particles(p) => {
                let mut scene = self.scene.clone();
                scene.particles = Some(p);
                self.set_values(scene)
            }
            Action::Tessellation(t) => {
                let mut scene = self.scene.clone();
                scene.tessellation = Some(t);
                self.set_values(scene)
            }
            Action::Skin(object, skin) => {
                let mut scene = self.scene.clone();
                scene.objects[object].skin = Some(skin);
                self.set_values(scene)
            }
            Action::Time(t) => {
                let mut scene = self.scene.clone();
                scene.set_time(t).and_then(|()| self.set_values(scene))
            }
            Action::ResetCamera => {
                self.orbit = super::Orbit::new(&self.scene.camera);
                Ok(())
            }
        };
        match result {
            Ok(()) => self.message = None,
            Err(e) => {
                eprintln!("gloss: {e:#}");
                self.message = Some(format!("{e:#}"));
            }
        }
    }

    pub(super) fn key(&mut self, key: KeyAction) {
        let mut settings = self.scene.render.clone();
        let action = match key {
            KeyAction::TogglePanel | KeyAction::Help | KeyAction::Fly | KeyAction::NextScale => {
                if let Some(run) = self.running.as_mut() {
                    match key {
                        KeyAction::Help => run.panel.help = !run.panel.help,
                        KeyAction::NextScale => run.panel.scale = run.panel.scale.next(),
                        KeyAction::Fly => {
                            run.fly = !run.fly;
                            run.held.clear();
                            self.status = Some(format!(
                                "fly mode {}",
                                if run.fly { "on (W A S D Q E)" } else { "off" }
                            ));
                        }
                        _ => run.panel.open = !run.panel.open,
                    }
                }
                return;
            }
            KeyAction::Screenshot(with_panel) => Action::Screenshot(with_panel),
            KeyAction::Reload => Action::Reload,
            KeyAction::ResetCamera => Action::ResetCamera,
            KeyAction::Path(i) => {
                settings.path = RenderPath::ALL[i.min(RenderPath::ALL.len() - 1)];
                Action::Settings(settings)
            }
            KeyAction::NextShading => {
                let i = Shading::ALL.iter().position(|&s| s == settings.shading);
                settings.shading = Shading::ALL[(i.unwrap_or(0) + 1) % Shading::ALL.len()];
                Action::Settings(settings)
            }
            KeyAction::ToggleStencil => {
                settings.stencil_volumes = !settings.stencil_volumes;
                Action::Settings(settings)
            }
            KeyAction::ToggleAreaLights => {
                settings.area_lights = !settings.area_lights;
                Action::Settings(settings)
            }
            KeyAction::NextView => {
                let Some(run) = self.running.as_ref() else {
                    return;
                };
                let n = super::frame::all_views(run).len();
                Action::Inspect(match run.panel.inspect {
                    None if n > 0 => Some(0),
                    Some(i) if i + 1 < n => Some(i + 1),
                    _ => None,
                })
            }
            KeyAction::Quit => return,
        };
        self.apply(action);
    }

    /// Give the renderer `scene`'s edited values and keep them.
    pub(super) fn set_values(&mut self, scene: Scene) -> Result<()> {
        if let Some(run) = self.running.as_mut() {
            run.renderer.set_scene_values(&scene)?;
        }
        self.scene = scene;
        Ok(())
    }

    /// Load `path` (with the command line's overrides) and make it the
    /// scene; on any error the old scene keeps running.
    fn load(&mut self, path: &Path) -> Result<()> {
        let scene = Scene::load_with(path, &self.options.overrides)?;
        self.rebuild(&scene)?;
        scene.print_warnings(&scene.warnings());
        if let Some(run) = self.running.as_mut() {
            run.panel.inspect = None;
        }
        self.orbit = super::Orbit::new(&scene.camera);
        self.scene = scene;
        self.scene_path = path.to_path_buf();
        self.scene_seen = modified(path);
        self.status = Some(format!("loaded {}", path.display()));
        Ok(())
    }

    /// A new renderer for `scene` at the view's size; the old one stays on error.
    pub(super) fn rebuild(&mut self, scene: &Scene) -> Result<()> {
        let Some(run) = self.running.as_mut() else {
            return Ok(());
        };
        // At the view's size, as the old one was (src/demo/frame.rs).
        let (w, h) = (run.renderer.width, run.renderer.height);
        let renderer = Renderer::new(&run.ctx.gl, &run.ctx.debug, scene, &self.sources, w, h)?;
        run.renderer = renderer;
        Ok(())
    }

    /// Twice a second: has the scene file or a shader in glsl/ changed on
    /// disk? Then load it again; a failure is shown and the old one kept.
    pub(super) fn reload_if_changed(&mut self) {
        let Some(run) = self.running.as_mut() else {
            return;
        };
        if run.checked.elapsed() < Duration::from_millis(500) {
            return;
        }
        run.checked = Instant::now();
        let shaders = self.sources.modified(&shader_names());
        if shaders != run.shaders_seen {
            run.shaders_seen = shaders;
            let scene = self.scene.clone();
            match self.rebuild(&scene) {
                Ok(()) => self.status = Some("shaders reloaded from glsl/".into()),
                Err(e) => {
                    eprintln!("gloss: shader reload failed, keeping the old shaders:\n{e:#}");
                    self.message = Some(format!("shader reload failed: {e:#}"));
                }
            }
        }
        let scene = modified(&self.scene_path);
        if scene.is_some() && scene != self.scene_seen {
            self.scene_seen = scene;
            self.apply(Action::Reload);
        }
    }
}

/// Lights as the panel edited them, checked as the scene loader checks a
/// file's: attenuation coefficients valid, a direction that is not zero
/// (made unit), a spot's inner angle within its outer one, no more casting
/// lights than there are shadow-map units (the panel refuses them already).
fn checked(mut lights: Vec<Light>) -> Result<Vec<Light>> {
    if let Some(e) = super::panel::too_many_casters(&lights) {
        bail!("{e}");
    }
    for (i, l) in lights.iter_mut().enumerate() {
        validate_attenuation(l.kc, l.kl, l.kq).map_err(|e| anyhow!("light {i}: {e}"))?;
        if l.direction.length() < 1e-6 {
            bail!("light {i}: the direction must not be zero");
        }
        l.direction = l.direction.normalize();
        l.inner_angle = l.inner_angle.min(l.outer_angle);
    }
    Ok(lights)
}

/// Objects as the panel edited them: no object may be its own ancestor.
fn no_parent_cycle(objects: &[crate::scene::Object]) -> Result<()> {
    for (i, o) in objects.iter().enumerate() {
        let mut up = o.parent;
        for _ in 0..objects.len() {
            let Some(p) = up else { break };
            if p == i {
                bail!(
                    "object {}: that parent would make it its own ancestor",
                    o.name
                );
            }
            up = objects.get(p).and_then(|q| q.parent);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::no_parent_cycle;

    #[test]
    fn a_parent_that_makes_a_cycle_is_refused() {
        let mut objects = crate::scene::Scene::load(std::path::Path::new("scenes/default.toml"))
            .unwrap()
            .objects;
        assert!(no_parent_cycle(&objects).is_ok());
        // The rock is the box's child; the box made the rock's child: a cycle.
        let rock = objects.iter().position(|o| o.name == "rock").unwrap();
        let box_ = objects[rock].parent.unwrap();
        objects[box_].parent = Some(rock);
        let e = no_parent_cycle(&objects).unwrap_err().to_string();
        assert!(e.contains("its own ancestor"), "{e}");
        // Its own parent.
        objects[box_].parent = Some(box_);
        assert!(no_parent_cycle(&objects).is_err());
    }
}
