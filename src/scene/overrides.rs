//! `--set KEY=VALUE` (and the bench's `--vary`): a value written into the
//! parsed scene file before it is checked, as if the file said it.
//!
//! KEY is a dotted path (`render.cutoff`). A part may index an array of
//! tables: `lights[0].intensity`, or `lights[*].shadow.resolution` for every
//! light. A `true` where a table is needed becomes an empty table, as
//! `shadow = true` means the defaults (`lights[0].shadow.bias=0`).

use anyhow::{Result, anyhow, bail};

/// The most dotted parts a `--set` key may have. The deepest key a scene
/// has is four parts (`materials.glass.microfacet.roughness`); each part
/// is a level of recursion here and in every later walk of the tables, so
/// a key of tens of thousands of parts would overflow the stack.
pub const MAX_KEY_PARTS: usize = 16;

/// Set `table.key = value` in a parsed scene file, making tables as needed.
pub(super) fn apply_override(table: &mut toml::Table, assignment: &str) -> Result<()> {
    let (key, value) = assignment
        .split_once('=')
        .ok_or_else(|| anyhow!("expected KEY=VALUE, such as render.cutoff=0.01"))?;
    let (key, value) = (key.trim(), value.trim());
    let value = match toml::from_str::<toml::Table>(&format!("v = {value}")) {
        Ok(mut t) => t.remove("v").expect("the one key"),
        Err(_) => toml::Value::String(value.to_string()),
    };
    // Counted before anything is split or made.
    let count = key.split('.').count();
    if count > MAX_KEY_PARTS {
        bail!(
            "the key has {count} dotted parts; a scene key has at most {MAX_KEY_PARTS} (the deepest, such as materials.glass.microfacet.roughness, has 4)"
        );
    }
    let parts: Vec<&str> = key.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        bail!("empty key");
    }
    set(table, &parts, &value)
}

/// Which entries of an array `name[i]` or `name[*]` picks.
enum Index {
    One(usize),
    All,
}

fn split_index(part: &str) -> Result<(&str, Option<Index>)> {
    let Some((name, rest)) = part.split_once('[') else {
        return Ok((part, None));
    };
    let inner = rest
        .strip_suffix(']')
        .ok_or_else(|| anyhow!("{part}: expected name[index] or name[*]"))?;
    let index = match inner {
        "*" => Index::All,
        n => Index::One(
            n.parse()
                .map_err(|_| anyhow!("{part}: expected name[index] or name[*]"))?,
        ),
    };
    Ok((name, Some(index)))
}

fn set(t: &mut toml::Table, parts: &[&str], value: &toml::Value) -> Result<()> {
    let (first, rest) = parts.split_first().expect("at least one part");
    let (name, index) = split_index(first)?;
    if rest.is_empty() {
        if index.is_some() {
            bail!("{first}: set a key of the entry, such as {first}.intensity");
        }
        t.insert(name.to_string(), value.clone());
        return Ok(());
    }
    let Some(index) = index else {
        let entry = t
            .entry(name)
            .or_insert_with(|| toml::Value::Table(toml::Table::new()));
        if *entry == toml::Value::Boolean(true) {
            *entry = toml::Value::Table(toml::Table::new());
        }
        let inner = entry
            .as_table_mut()
            .ok_or_else(|| anyhow!("{name} is not a table"))?;
        return set(inner, rest, value);
    };
    let array = t
        .get_mut(name)
        .and_then(toml::Value::as_array_mut)
        .ok_or_else(|| anyhow!("{name} is not an array of tables in this scene"))?;
    let len = array.len();
    let entries: Vec<&mut toml::Value> = match index {
        Index::All => array.iter_mut().collect(),
        Index::One(i) => vec![
            array
                .get_mut(i)
                .ok_or_else(|| anyhow!("{name}[{i}]: the scene has {len} {name}"))?,
        ],
    };
    for e in entries {
        let inner = e
            .as_table_mut()
            .ok_or_else(|| anyhow!("{name} is not an array of tables"))?;
        set(inner, rest, value)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::apply_override;

    fn table(text: &str) -> toml::Table {
        toml::from_str(text).unwrap()
    }

    #[test]
    fn dotted_keys_make_tables() {
        let mut t = table("");
        apply_override(&mut t, "render.cutoff=0.01").unwrap();
        assert_eq!(t["render"]["cutoff"].as_float(), Some(0.01));
        apply_override(&mut t, "render.path=volumes").unwrap();
        assert_eq!(t["render"]["path"].as_str(), Some("volumes"));
    }

    #[test]
    fn an_entry_or_every_entry_of_an_array() {
        let text = "[[lights]]\nshadow = true\n[[lights]]\nintensity = 2.0\n";
        let mut t = table(text);
        apply_override(&mut t, "lights[1].intensity=3.0").unwrap();
        assert_eq!(t["lights"][1]["intensity"].as_float(), Some(3.0));
        // `shadow = true` becomes a table of the one key.
        apply_override(&mut t, "lights[0].shadow.resolution=512").unwrap();
        assert_eq!(
            t["lights"][0]["shadow"]["resolution"].as_integer(),
            Some(512)
        );
        apply_override(&mut t, "lights[*].color=[1, 0, 0]").unwrap();
        assert!(t["lights"][1]["color"].is_array());
        for bad in [
            "lights[2].intensity=1",
            "lights[x].intensity=1",
            "lights[0=1",
            "lights[0]=1",
            "camera[0].eye=1",
            "render..x=1",
            &format!("render{}=1", ".x".repeat(16)),
        ] {
            assert!(apply_override(&mut table(text), bad).is_err(), "{bad}");
        }
    }
}
