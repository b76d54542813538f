//! How a traced argument is shown: GL constants by name within the
//! argument's group (gl.xml's groups, as glow documents them), bitfields as
//! their bits, booleans as GL_TRUE / GL_FALSE, names as strings.

use super::names::NAMES;
use std::ffi::{CStr, c_void};

/// A pointer argument (any pointee: the shims only pass it on).
pub type Ptr = *const c_void;

/// How an argument is read.
#[derive(Clone, Copy, Debug)]
pub enum Kind {
    /// A constant of this group ("" when glow names none).
    Enum(&'static str),
    /// A bitfield of this group's bits.
    Mask(&'static str),
    Bool,
    Num,
    /// A NUL-terminated name (a uniform's, a block's).
    Str,
    Ptr,
}

/// An argument or a result as the driver saw it.
#[derive(Clone, Copy, Debug)]
pub enum Raw {
    Int(i64),
    Float(f64),
    Ptr(usize),
}

macro_rules! raw_from {
    ($variant:ident as $to:ty: $($t:ty),*) => {
        $(impl From<$t> for Raw {
            fn from(v: $t) -> Raw {
                Raw::$variant(v as $to)
            }
        })*
    };
}
raw_from!(Int as i64: u32, i32, u8, i8, u16, i16, u64, i64, isize);
raw_from!(Float as f64: f32, f64);
raw_from!(Ptr as usize: Ptr);

/// A shim's result: `()` has none.
pub trait Result_ {
    fn raw(&self) -> Option<Raw>;
}
impl Result_ for () {
    fn raw(&self) -> Option<Raw> {
        None
    }
}
macro_rules! result_of {
    ($($t:ty),*) => {
        $(impl Result_ for $t {
            fn raw(&self) -> Option<Raw> {
                Some(Raw::from(*self))
            }
        })*
    };
}
result_of!(u32, i32, u8, Ptr);

impl Raw {
    pub fn result(out: &impl Result_) -> Option<Raw> {
        out.raw()
    }

    pub fn int(self) -> i64 {
        match self {
            Raw::Int(v) => v,
            Raw::Float(v) => v as i64,
            Raw::Ptr(p) => p as i64,
        }
    }

    /// The argument as the trace prints it.
    pub fn show(self, kind: Kind) -> String {
        match (kind, self) {
            (_, Raw::Float(v)) => format!("{v}"),
            (Kind::Str, Raw::Ptr(0)) => "NULL".into(),
            // An offset into a bound buffer, or the address of data in
            // memory (which changes from run to run: not printed).
            (Kind::Ptr, Raw::Ptr(p)) if p < 1 << 20 => format!("{p}"),
            (Kind::Ptr, Raw::Ptr(_)) => "&data".into(),
            // SAFETY: shims mark as Str only the NUL-terminated names GL reads.
            (Kind::Str, Raw::Ptr(p)) => {
                let s = unsafe { CStr::from_ptr(p as *const std::ffi::c_char) };
                format!("{:?}", s.to_string_lossy())
            }
            (Kind::Bool, Raw::Int(0)) => "GL_FALSE".into(),
            (Kind::Bool, Raw::Int(1)) => "GL_TRUE".into(),
            (Kind::Enum(group), Raw::Int(v)) if (0..=u32::MAX as i64).contains(&v) => {
                constant_name(v as u32, group).map_or_else(|| format!("{v:#x}"), str::to_string)
            }
            (Kind::Mask(group), Raw::Int(v)) => mask(v as u32, group),
            (_, raw) => format!("{}", raw.int()),
        }
    }
}

/// The name of constant `value` in `group`: a constant gloss names that
/// belongs to the group; outside any group, one gloss names, above the
/// small values (0-7) that mean something else in every group.
pub fn constant_name(value: u32, group: &str) -> Option<&'static str> {
    let of_value = || NAMES.iter().filter(move |(v, _, _)| *v == value);
    of_value()
        .find(|(_, _, groups)| groups.contains(&group))
        .or_else(|| of_value().next().filter(|_| value > 7))
        .map(|(_, name, _)| *name)
}

/// `GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT`; bits with no name in hex.
fn mask(value: u32, group: &str) -> String {
    if value == 0 {
        return "0".into();
    }
    let mut parts = Vec::new();
    let mut left = value;
    for bit in (0..32).map(|i| 1u32 << i).filter(|b| value & b != 0) {
        let named = NAMES
            .iter()
            .find(|(v, _, groups)| *v == bit && groups.contains(&group));
        if let Some((_, name, _)) = named {
            parts.push(name.to_string());
            left &= !bit;
        }
    }
    if left != 0 {
        parts.push(format!("{left:#x}"));
    }
    parts.join(" | ")
}
