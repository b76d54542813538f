//! Who gets each window event, decided when it happens: a key is the
//! demo's unless a text field of the panel is being edited (Tab included:
//! egui would take it to move its focus); a press in the 3D view belongs
//! to the camera and takes the keyboard focus from the panel, a press over
//! the panel to egui; every release goes to both and ends every drag of the
//! camera (docs/demo.md, "Input").

use super::{Demo, Running, keys};
use anyhow::Result;
use winit::dpi::PhysicalPosition;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::ActiveEventLoop;

impl Demo {
    pub(super) fn handle(
        &mut self,
        event_loop: &ActiveEventLoop,
        event: WindowEvent,
    ) -> Result<()> {
        if event == WindowEvent::RedrawRequested {
            if self.frame()? {
                event_loop.exit();
            }
            return Ok(());
        }
        let Some(run) = self.running.as_mut() else {
            return Ok(());
        };
        // Who gets the event is decided here, before egui sees it: a key is
        // the demo's unless a text field is being edited (egui would take
        // Tab to move its focus); a press belongs to egui over the panel and
        // to the camera in the view; every release goes to both and ends
        // every drag of the camera.
        let editing = run.egui.egui_ctx.text_edit_focused();
        if let WindowEvent::KeyboardInput { event: key, .. } = &event
            && !editing
            && (keys::action(&key.logical_key, false).is_some()
                || (run.fly && fly_key(&key.logical_key).is_some()))
        {
            run.panel_layer.stale = true;
            return self.demo_key(event_loop, key);
        }
        if let WindowEvent::MouseInput {
            state: ElementState::Pressed,
            button,
            ..
        } = event
            && run.in_view(run.cursor)
        {
            // A click in the view takes the keyboard focus from the panel.
            run.egui.egui_ctx.memory_mut(|m| m.stop_text_input());
            run.panel_layer.stale = true;
            match button {
                MouseButton::Left => {
                    run.left_down = true;
                    run.pressed();
                }
                MouseButton::Right | MouseButton::Middle => run.pan_down = true,
                _ => {}
            }
            return Ok(());
        }
        if let WindowEvent::MouseInput {
            state: ElementState::Released,
            ..
        } = event
        {
            if run.left_down {
                run.released();
            }
            run.left_down = false;
            run.pan_down = false;
        }
        let to_egui = run.egui.on_window_event(&run.ctx.window, &event);
        // What egui sees shows in the panel.
        if to_egui.repaint {
            run.panel_layer.stale = true;
        }
        match event {
            WindowEvent::CloseRequested | WindowEvent::Destroyed => event_loop.exit(),
            // A zero size (minimised) keeps the old size until the window comes back.
            WindowEvent::Resized(size) if size.width > 0 && size.height > 0 => {
                run.ctx.resize(size.width, size.height);
                run.panel_layer.stale = true;
            }
            WindowEvent::ModifiersChanged(m) => run.modifiers = m.state(),
            WindowEvent::CursorMoved { position, .. } => {
                if let Some(last) = run.cursor {
                    let (dx, dy) = ((position.x - last.x) as f32, (position.y - last.y) as f32);
                    match (run.left_down, run.pan_down, run.fly) {
                        (true, _, false) => self.orbit.rotate(dx, dy),
                        (true, _, true) => self.orbit.look(dx, dy),
                        (false, true, _) => self.orbit.pan(dx, dy),
                        _ => {}
                    }
                }
                run.cursor = Some(position);
            }
            WindowEvent::CursorLeft { .. } => run.cursor = None,
            WindowEvent::MouseWheel { delta, .. } if run.in_view(run.cursor) => {
                self.orbit.zoom(match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                })
            }
            _ => {}
        }
        Ok(())
    }

    /// A key of the demo's (keys.rs, or a fly-mode key while flying).
    fn demo_key(
        &mut self,
        event_loop: &ActiveEventLoop,
        key: &winit::event::KeyEvent,
    ) -> Result<()> {
        let Some(run) = self.running.as_mut() else {
            return Ok(());
        };
        let pressed = key.state == ElementState::Pressed;
        if run.fly
            && let Some(k) = fly_key(&key.logical_key)
        {
            if pressed {
                run.held.insert(k);
            } else {
                run.held.remove(&k);
            }
            return Ok(());
        }
        if !pressed {
            return Ok(());
        }
        match keys::action(&key.logical_key, run.modifiers.shift_key()) {
            Some(keys::KeyAction::Quit) => event_loop.exit(),
            Some(a) => self.key(a),
            None => {}
        }
        Ok(())
    }
}

impl Running {
    /// Is the pointer at `cursor` over the 3D view (not over the panel, nor
    /// over one of egui's windows or menus laid over the view)?
    pub(super) fn in_view(&self, cursor: Option<PhysicalPosition<f64>>) -> bool {
        let Some(c) = cursor else {
            return false;
        };
        let [x, y, w, h] = self.view;
        let inside = c.x >= f64::from(x)
            && c.y >= f64::from(y)
            && c.x < f64::from(x + w)
            && c.y < f64::from(y + h);
        let ppp = f64::from(self.egui.egui_ctx.pixels_per_point());
        let at = egui::pos2((c.x / ppp) as f32, (c.y / ppp) as f32);
        let over_egui = (self.egui.egui_ctx.layer_id_at(at))
            .is_some_and(|l| l.order != egui::Order::Background);
        inside && !over_egui
    }
}

/// W A S D Q E, the fly-mode keys.
fn fly_key(key: &winit::keyboard::Key) -> Option<char> {
    match key {
        winit::keyboard::Key::Character(c) => {
            let c = c.to_lowercase().chars().next()?;
            "wasdqe".contains(c).then_some(c)
        }
        _ => None,
    }
}
