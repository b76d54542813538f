//! The demo's keys: one table, shown in the panel and by F1.

pub const KEYS: &[(&str, &str)] = &[
    ("Tab", "show or hide the panel"),
    ("F1", "this list"),
    (
        "F12 or P",
        "screenshot (the frame, without the panel) to gloss-screenshot-N.png",
    ),
    ("Shift+F12", "screenshot with the panel"),
    ("F5", "reload the scene file"),
    (
        "F2",
        "render scale: 1, 1/2, 1/4 of the view's pixels (shown scaled up)",
    ),
    (
        "1 2 3 4",
        "lighting path: forward, deferred, volumes, prepass",
    ),
    ("G", "next shading mode (flat, Gouraud, Phong)"),
    ("V", "stencil light volumes on or off"),
    ("L", "area lights (LTC) on or off"),
    ("I", "next pass-inspector view"),
    ("R", "reset the camera to the scene's"),
    (
        "F",
        "fly mode on or off: drag turns the view, W A S D move, Q E down and up",
    ),
    (
        "left click (in the view)",
        "probe that pixel (the panel's \"Pixel probe\")",
    ),
    ("left drag, wheel", "orbit, zoom"),
    ("right or middle drag", "pan"),
    ("Esc", "quit"),
];

/// What a key does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KeyAction {
    TogglePanel,
    Help,
    /// A screenshot; `true`: with the panel.
    Screenshot(bool),
    Reload,
    /// The next render scale (1, 1/2, 1/4).
    NextScale,
    Path(usize),
    NextShading,
    ToggleStencil,
    ToggleAreaLights,
    NextView,
    ResetCamera,
    Fly,
    Quit,
}

/// The action of a pressed key, if it has one.
pub fn action(key: &winit::keyboard::Key, shift: bool) -> Option<KeyAction> {
    use winit::keyboard::{Key, NamedKey};
    Some(match key {
        Key::Named(NamedKey::Tab) => KeyAction::TogglePanel,
        Key::Named(NamedKey::F1) => KeyAction::Help,
        Key::Named(NamedKey::F12) => KeyAction::Screenshot(shift),
        Key::Named(NamedKey::F5) => KeyAction::Reload,
        Key::Named(NamedKey::F2) => KeyAction::NextScale,
        Key::Named(NamedKey::Escape) => KeyAction::Quit,
        Key::Character(c) => match c.to_lowercase().as_str() {
            "p" => KeyAction::Screenshot(shift),
            "1" => KeyAction::Path(0),
            "2" => KeyAction::Path(1),
            "3" => KeyAction::Path(2),
            "4" => KeyAction::Path(3),
            "g" => KeyAction::NextShading,
            "v" => KeyAction::ToggleStencil,
            "l" => KeyAction::ToggleAreaLights,
            "i" => KeyAction::NextView,
            "r" => KeyAction::ResetCamera,
            "f" => KeyAction::Fly,
            _ => return None,
        },
        _ => return None,
    })
}
