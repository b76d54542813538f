//! Shader programs built from the files in glsl/.
//!
//! * The sources are embedded in the binary (include_dir), so gloss runs from
//!   any directory; the demo can instead read them from glsl/ on disk and
//!   rebuild a program when a file changes.
//! * `#include "file.glsl"` pastes a shared file (the lighting functions) in
//!   place. Each line of the pasted text remembers its file and line, and a
//!   compile error is reported as `glsl/<file>:<line>: <message>`. (No `#line`
//!   directives: Mesa drops their source-string number from most messages,
//!   which would blame an included file's error on the file that includes it.)
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

/// A preprocessed shader: its text, the files pasted into it (the main file
/// first), and where each of its lines came from.
pub struct Preprocessed {
    pub text: String,
    pub files: Vec<String>,
    /// For line `n` (1-based) of `text`, `lines[n - 1]` is (index into `files`,
    /// 1-based line in that file); inserted `#define`s count as the `#version` line.
    pub lines: Vec<(usize, usize)>,
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
        lines: Vec::new(),
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
        } else {
            out.text.push_str(line);
            out.text.push('\n');
            out.lines.push((file_no, i + 1));
            if trimmed.starts_with("#version") {
                for (k, v) in defines {
                    out.text.push_str(&format!("#define {k} {v}\n"));
                    out.lines.push((file_no, i + 1));
                }
            }
        }
    }
    Ok(())
}

/// Rewrite a driver's info log so that `0:12(5): error` (Mesa) or `0(12) : error`
/// (NVIDIA), line 12 of the preprocessed text, reads `glsl/<file>:<line>: error`
/// with the file and line that text came from.
pub fn translate_log(log: &str, pre: &Preprocessed) -> String {
    let mut out = Vec::new();
    for line in log.lines().filter(|l| !l.trim().is_empty()) {
        let parsed = (|| {
            let digits_end = line.find(|c: char| !c.is_ascii_digit())?;
            let _source: usize = line[..digits_end].parse().ok()?;
            let rest = &line[digits_end..];
            let rest = rest.strip_prefix(':').or_else(|| rest.strip_prefix('('))?;
            let l_end = rest.find(|c: char| !c.is_ascii_digit())?;
            let lineno: usize = rest[..l_end].parse().ok()?;
            let msg = rest[l_end..]
                .trim_start_matches(|c: char| c == ')' || c == '(' || c.is_ascii_digit())
                .trim_start_matches([')', ' ', ':']);
            let &(file, file_line) = pre.lines.get(lineno.checked_sub(1)?)?;
            Some(format!("glsl/{}:{file_line}: {msg}", pre.files.get(file)?))
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
        Program::with_feedback(gl, sources, stages, defines, &[])
    }

    /// `new`, for a program whose vertex shader's outputs `varyings` are
    /// captured by transform feedback, interleaved in that order into one
    /// buffer: glTransformFeedbackVaryings(..., GL_INTERLEAVED_ATTRIBS)
    /// before the link, as GL requires.
    pub fn with_feedback(
        gl: &Gl,
        sources: &Sources,
        stages: &[(u32, &str)],
        defines: &[(&str, String)],
        varyings: &[&str],
    ) -> Result<Program> {
        let name = stages.iter().map(|s| s.1).collect::<Vec<_>>().join(" + ");
        unsafe {
            let program = gl
                .create_program()
                .map_err(|e| anyhow!("glCreateProgram: {e}"))?;
            super::live::made(super::live::Kind::Program);
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
                            translate_log(&log, &pre)
                        );
                    }
                    gl.attach_shader(program, sh);
                }
                if !varyings.is_empty() {
                    gl.transform_feedback_varyings(program, varyings, glow::INTERLEAVED_ATTRIBS);
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
                super::live::freed(super::live::Kind::Program);
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

    /// glUseProgram(0)
    pub fn unuse(&self) {
        unsafe { self.gl.use_program(None) }
    }

    fn loc(&self, name: &str) -> Option<glow::UniformLocation> {
        if let Some(l) = self.locations.borrow().get(name) {
            return *l;
        }
        let l = unsafe { self.gl.get_uniform_location(self.id, name) };
        self.locations.borrow_mut().insert(name.to_owned(), l);
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
    pub fn set_ivec3(&self, name: &str, v: glam::IVec3) {
        unsafe {
            self.gl
                .uniform_3_i32(self.loc(name).as_ref(), v.x, v.y, v.z)
        }
    }
    pub fn set_bool(&self, name: &str, v: bool) {
        self.set_i32(name, v as i32)
    }
    /// A `float name[N]` array from its first element (glUniform1fv).
    /// glUniformMatrix4fv with `m.len()` matrices, from element 0 of the array `name`.
    pub fn set_mat4_array(&self, name: &str, m: &[glam::Mat4]) {
        let flat: Vec<f32> = m.iter().flat_map(|x| x.to_cols_array()).collect();
        unsafe {
            self.gl
                .uniform_matrix_4_f32_slice(self.loc(name).as_ref(), false, &flat)
        }
    }

    /// glUniform4fv with `v.len()` vectors, from element 0 of the array `name`.
    pub fn set_vec4_array(&self, name: &str, v: &[glam::Vec4]) {
        let flat: Vec<f32> = v.iter().flat_map(|x| x.to_array()).collect();
        unsafe { self.gl.uniform_4_f32_slice(self.loc(name).as_ref(), &flat) }
    }

    pub fn set_f32_array(&self, name: &str, v: &[f32]) {
        unsafe { self.gl.uniform_1_f32_slice(self.loc(name).as_ref(), v) }
    }

    /// glUniformBlockBinding: attach the named std140 block to binding point `binding`.
    pub fn bind_uniform_block(&self, block: &str, binding: u32) {
        unsafe {
            if let Some(idx) = self.gl.get_uniform_block_index(self.id, block) {
                self.gl.uniform_block_binding(self.id, idx, binding);
            }
        }
    }

    /// Whether the linked program has the active uniform `name`
    /// (glGetUniformLocation, cached as the setters cache it).
    pub fn has_uniform(&self, name: &str) -> bool {
        self.loc(name).is_some()
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        unsafe {
            self.gl.delete_program(self.id);
            super::live::freed(super::live::Kind::Program);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mesa_and_nvidia_logs_name_file_and_line() {
        let dir = std::env::temp_dir().join("gloss-program-translate-log");
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("main.frag"),
            "#version 330 core\n#include \"inc.glsl\"\nfloat x = foo;\n",
        )
        .unwrap();
        std::fs::write(dir.join("inc.glsl"), "// shared\nfloat y = bar;\n").unwrap();
        let pre = preprocess(
            &Sources::Directory(dir),
            "main.frag",
            &[("MAX_LIGHTS", "4".to_owned())],
        )
        .unwrap();
        assert_eq!(
            pre.text,
            "#version 330 core\n#define MAX_LIGHTS 4\n// shared\nfloat y = bar;\nfloat x = foo;\n"
        );
        // Mesa gives the source number 0 whatever the file; the line decides.
        let mesa = "0:4(11): error: `bar' undeclared";
        assert_eq!(
            translate_log(mesa, &pre),
            "glsl/inc.glsl:2: error: `bar' undeclared"
        );
        let nv = "0(5) : error C1008: undefined variable \"foo\"";
        assert_eq!(
            translate_log(nv, &pre),
            "glsl/main.frag:3: error C1008: undefined variable \"foo\""
        );
        // A line the text does not have is left as the driver wrote it.
        assert_eq!(translate_log("0:99(1): odd", &pre), "0:99(1): odd");
    }
}
