//! Shader programs built from the files in glsl/.
//!
//! * The sources are embedded in the binary (include_dir), so gloss runs from
//!   any directory; the demo can instead read them from glsl/ on disk and
//!   rebuild a program when a file changes.
//! * `#include "file.glsl"` pastes a shared file (the lighting functions) in
//!   place; `#line` directives keep line numbers right, and a compile error is
//!   reported as `glsl/<file>:<line>: <message>`.
//! * `#define`s (such as MAX_LIGHTS) are inserted after the `#version` line.

use super::Gl;
use anyhow::{Result, anyhow, bail};
use glow::HasContext;
use include_dir::{Dir, include_dir};
use std::cell::RefCell;
use std::collections::HashMap;
use std::path::PathBuf;

static EMBEDDED: Dir<'static> = include_dir!("$CARGO_MANIFEST_DIR/glsl");

/// Where shader text comes from.
#[derive(Clone, Debug)]
pub enum Sources {
    /// Compiled into the binary.
    Embedded,
    /// Read from a directory (the demo's live reload of glsl/).
    Directory(PathBuf),
}

impl Sources {
    pub fn read(&self, name: &str) -> Result<String> {
        match self {
            Sources::Embedded => EMBEDDED
                .get_file(name)
                .and_then(|f| f.contents_utf8())
                .map(str::to_owned)
                .ok_or_else(|| anyhow!("no shader glsl/{name} is embedded in gloss")),
            Sources::Directory(dir) => std::fs::read_to_string(dir.join(name))
                .map_err(|e| anyhow!("cannot read shader {}: {e}", dir.join(name).display())),
        }
    }

    /// Latest modification time of the named files (for live reload).
    pub fn modified(&self, names: &[&str]) -> Option<std::time::SystemTime> {
        match self {
            Sources::Embedded => None,
            Sources::Directory(dir) => names
                .iter()
                .filter_map(|n| {
                    std::fs::metadata(dir.join(n))
                        .and_then(|m| m.modified())
                        .ok()
                })
                .max(),
        }
    }
}

/// Every embedded shader file name (tests compile them all).
pub fn embedded_names() -> Vec<String> {
    let mut v = Vec::new();
    fn walk(d: &Dir<'static>, v: &mut Vec<String>) {
        for f in d.files() {
            v.push(f.path().to_string_lossy().into_owned());
        }
        for s in d.dirs() {
            walk(s, v);
        }
    }
    walk(&EMBEDDED, &mut v);
    v.sort();
    v
}

/// A preprocessed shader: its text and the file each `#line` source number stands for.
pub struct Preprocessed {
    pub text: String,
    pub files: Vec<String>,
}

/// Expand `#include "x"` and insert `defines` after `#version`.
pub fn preprocess(
    sources: &Sources,
    name: &str,
    defines: &[(&str, String)],
) -> Result<Preprocessed> {
    let mut out = Preprocessed {
        text: String::new(),
        files: Vec::new(),
    };
    expand(sources, name, defines, &mut out, 0)?;
    Ok(out)
}

fn expand(
    sources: &Sources,
    name: &str,
    defines: &[(&str, String)],
    out: &mut Preprocessed,
    depth: usize,
) -> Result<()> {
    if depth > 8 {
        bail!("glsl/{name}: #include nested more than 8 deep (a cycle?)");
    }
    let text = sources.read(name)?;
    let file_no = out.files.len();
    out.files.push(name.to_owned());
    for (i, line) in text.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix("#include") {
            let inc = rest.trim().trim_matches('"');
            if inc.is_empty() {
                bail!(
                    "glsl/{name}:{}: #include needs a file name in quotes",
                    i + 1
                );
            }
            expand(sources, inc, &[], out, depth + 1)?;
            out.text.push_str(&format!("#line {} {file_no}\n", i + 2));
        } else if trimmed.starts_with("#version") {
            out.text.push_str(line);
            out.text.push('\n');
            for (k, v) in defines {
                out.text.push_str(&format!("#define {k} {v}\n"));
            }
            out.text.push_str(&format!("#line {} {file_no}\n", i + 2));
        } else {
            if i == 0 && depth > 0 {
                out.text.push_str(&format!("#line 1 {file_no}\n"));
            }
            out.text.push_str(line);
            out.text.push('\n');
        }
    }
    Ok(())
}

/// Rewrite a driver's info log so that `0:12(5): error` (Mesa) or `0(12) : error`
/// (NVIDIA) reads `glsl/forward.frag:12: error`.
pub fn translate_log(log: &str, files: &[String]) -> String {
    let mut out = Vec::new();
    for line in log.lines().filter(|l| !l.trim().is_empty()) {
        let parsed = (|| {
            let digits_end = line.find(|c: char| !c.is_ascii_digit())?;
            let file: usize = line[..digits_end].parse().ok()?;
            let rest = &line[digits_end..];
            let rest = rest.strip_prefix(':').or_else(|| rest.strip_prefix('('))?;
            let l_end = rest.find(|c: char| !c.is_ascii_digit())?;
            let lineno: usize = rest[..l_end].parse().ok()?;
            let msg = rest[l_end..]
                .trim_start_matches(|c: char| c == ')' || c == '(' || c.is_ascii_digit())
                .trim_start_matches([')', ' ', ':']);
            Some(format!("glsl/{}:{lineno}: {msg}", files.get(file)?))
        })();
        out.push(parsed.unwrap_or_else(|| line.to_owned()));
    }
    out.join("\n")
}

/// One linked program. Uniform locations are looked up once and cached.
pub struct Program {
    gl: Gl,
    pub id: glow::Program,
    pub name: String,
    locations: RefCell<HashMap<String, Option<glow::UniformLocation>>>,
}

impl Program {
    /// Compile and link `stages` = [(GL_VERTEX_SHADER, "forward.vert"), ...].
    pub fn new(
        gl: &Gl,
        sources: &Sources,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
    ) -> Result<Program> {
        let name = stages.iter().map(|s| s.1).collect::<Vec<_>>().join(" + ");
        unsafe {
            let program = gl
                .create_program()
                .map_err(|e| anyhow!("glCreateProgram: {e}"))?;
            let mut shaders = Vec::new();
            let result = (|| {
                for &(kind, file) in stages {
                    let pre = preprocess(sources, file, defines)?;
                    let sh = gl
                        .create_shader(kind)
                        .map_err(|e| anyhow!("glCreateShader: {e}"))?;
                    shaders.push(sh);
                    gl.shader_source(sh, &pre.text);
                    gl.compile_shader(sh);
                    if !gl.get_shader_compile_status(sh) {
                        let log = gl.get_shader_info_log(sh);
                        bail!(
                            "shader glsl/{file} failed to compile:\n{}",
                            translate_log(&log, &pre.files)
                        );
                    }
                    gl.attach_shader(program, sh);
                }
                gl.link_program(program);
                if !gl.get_program_link_status(program) {
                    bail!(
                        "program {name} failed to link:\n{}",
                        gl.get_program_info_log(program)
                    );
                }
                Ok(())
            })();
            for sh in shaders {
                gl.detach_shader(program, sh);
                gl.delete_shader(sh);
            }
            if let Err(e) = result {
                gl.delete_program(program);
                return Err(e);
            }
            Ok(Program {
                gl: gl.clone(),
                id: program,
                name,
                locations: RefCell::default(),
            })
        }
    }

    /// glUseProgram(id)
    pub fn use_program(&self) {
        unsafe { self.gl.use_program(Some(self.id)) }
    }

    fn loc(&self, name: &str) -> Option<glow::UniformLocation> {
        if let Some(l) = self.locations.borrow().get(name) {
            return l.clone();
        }
        let l = unsafe { self.gl.get_uniform_location(self.id, name) };
        self.locations
            .borrow_mut()
            .insert(name.to_owned(), l.clone());
        l
    }

    /// Uniform setters on the program in use (glUniform*). A name the
    /// linker optimised away is silently skipped, as GL does with location -1.
    pub fn set_mat4(&self, name: &str, m: &glam::Mat4) {
        unsafe {
            self.gl
                .uniform_matrix_4_f32_slice(self.loc(name).as_ref(), false, &m.to_cols_array())
        }
    }
    pub fn set_mat3(&self, name: &str, m: &glam::Mat3) {
        unsafe {
            self.gl
                .uniform_matrix_3_f32_slice(self.loc(name).as_ref(), false, &m.to_cols_array())
        }
    }
    pub fn set_vec4(&self, name: &str, v: glam::Vec4) {
        unsafe {
            self.gl
                .uniform_4_f32(self.loc(name).as_ref(), v.x, v.y, v.z, v.w)
        }
    }
    pub fn set_vec3(&self, name: &str, v: glam::Vec3) {
        unsafe {
            self.gl
                .uniform_3_f32(self.loc(name).as_ref(), v.x, v.y, v.z)
        }
    }
    pub fn set_vec2(&self, name: &str, v: glam::Vec2) {
        unsafe { self.gl.uniform_2_f32(self.loc(name).as_ref(), v.x, v.y) }
    }
    pub fn set_f32(&self, name: &str, v: f32) {
        unsafe { self.gl.uniform_1_f32(self.loc(name).as_ref(), v) }
    }
    pub fn set_i32(&self, name: &str, v: i32) {
        unsafe { self.gl.uniform_1_i32(self.loc(name).as_ref(), v) }
    }
    pub fn set_bool(&self, name: &str, v: bool) {
        self.set_i32(name, v as i32)
    }

    /// glUniformBlockBinding: attach the named std140 block to binding point `binding`.
    pub fn bind_uniform_block(&self, block: &str, binding: u32) {
        unsafe {
            if let Some(idx) = self.gl.get_uniform_block_index(self.id, block) {
                self.gl.uniform_block_binding(self.id, idx, binding);
            }
        }
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        unsafe { self.gl.delete_program(self.id) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_and_nvidia_logs_name_file_and_line() {
        let files = vec!["forward.frag".to_owned(), "lighting.glsl".to_owned()];
        let mesa = "1:12(5): error: `foo' undeclared";
        assert_eq!(
            translate_log(mesa, &files),
            "glsl/lighting.glsl:12: error: `foo' undeclared"
        );
        let nv = "0(7) : error C1008: undefined variable \"x\"";
        assert_eq!(
            translate_log(nv, &files),
            "glsl/forward.frag:7: error C1008: undefined variable \"x\""
        );
    }
}
