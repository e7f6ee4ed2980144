//! Which course framework a file was written for, read from its content.
//!
//! The 2016 framework writes CSG as `Object CSG` with its operands inside, has only point
//! lights, and upper-cases whole lines (so a file may name a material in another case
//! than its definition); its default material is white. The 2020 framework (and its
//! students' additions) has ambient, directional and spot lights, `CSG` and
//! `ObjectGroup` blocks of their own, and a magenta default material. Both read the
//! Scene block's `ambientLight`, so it tells nothing.
//!
//! A file with signs of 2016 and none of 2020 is read as 2016; anything else as 2020 (the
//! base reading), with a warning when it shows signs of both.

use std::collections::HashSet;
use std::fmt;

use super::super::syntax::{Block, CsgForm, ObjectKind, ObjectNode, ObjectSetting, ParsedBlock};
use crate::scene::LightKind;

/// The course framework a legacy file was written for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Dialect {
    /// The 2016 framework: white default material, names matched ignoring case.
    Framework2016,
    /// The 2020 framework and its students' additions (the base format).
    #[default]
    Framework2020,
}

impl fmt::Display for Dialect {
    /// "the 2016 framework's dialect" or "the 2020 framework's dialect".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Dialect::Framework2016 => "the 2016 framework's dialect",
            Dialect::Framework2020 => "the 2020 framework's dialect",
        })
    }
}

/// The dialect read, and the constructs that told it apart.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Detected {
    /// The dialect the file is read in.
    pub dialect: Dialect,
    /// Signs of the 2016 framework: (line, construct).
    pub signs_2016: Vec<(usize, String)>,
    /// Signs of the 2020 framework: (line, construct).
    pub signs_2020: Vec<(usize, String)>,
}

impl Detected {
    /// One phrase for the import summary: the dialect and the first sign of it.
    #[must_use]
    pub fn describe(&self) -> String {
        let signs = match self.dialect {
            Dialect::Framework2016 => &self.signs_2016,
            Dialect::Framework2020 => &self.signs_2020,
        };
        match signs.first() {
            Some((line, what)) => format!("{} ({what} at line {line})", self.dialect),
            None => format!(
                "{} (nothing in the file is specific to either)",
                self.dialect
            ),
        }
    }
}

/// Reads the dialect off the parsed blocks.
#[must_use]
pub fn detect(blocks: &[ParsedBlock]) -> Detected {
    let mut detected = Detected::default();
    let mut names = HashSet::new();
    for block in blocks {
        if let Block::Material { name, .. } = &block.block {
            names.insert(name.as_str());
        }
    }
    for block in blocks {
        let line = block.at.line;
        match &block.block {
            Block::Light { kind, .. } if *kind != LightKind::Point => {
                detected
                    .signs_2020
                    .push((line, format!("`Light {}`", block.at.token)));
            }
            Block::Object(node) => node_signs(node, &names, &mut detected),
            _ => {}
        }
    }
    detected.signs_2016.sort();
    detected.signs_2020.sort();
    if !detected.signs_2016.is_empty() && detected.signs_2020.is_empty() {
        detected.dialect = Dialect::Framework2016;
    }
    detected
}

/// The signs in one object tree: its CSG form, its groups, and material names that match
/// a definition only ignoring case.
fn node_signs(node: &ObjectNode, names: &HashSet<&str>, detected: &mut Detected) {
    let line = node.at.line;
    match &node.kind {
        ObjectKind::Csg { form, operands, .. } => {
            match form {
                CsgForm::Object2016 => detected.signs_2016.push((line, "`Object CSG`".into())),
                CsgForm::TopLevel => detected.signs_2020.push((line, "a `CSG` block".into())),
            }
            for operand in operands {
                node_signs(operand, names, detected);
            }
        }
        ObjectKind::Group(children) => {
            detected.signs_2020.push((line, "an `ObjectGroup`".into()));
            for child in children {
                node_signs(child, names, detected);
            }
        }
        _ => {}
    }
    for setting in &node.settings {
        if let ObjectSetting::Material(name) = &setting.value
            && !names.contains(name.as_str())
            && names.iter().any(|n| n.eq_ignore_ascii_case(name))
        {
            detected.signs_2016.push((
                setting.at.line,
                format!("material `{name}` named in another case"),
            ));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::error::Diagnostics;
    use super::super::super::lexer::{Comments, tokenize};
    use super::super::super::parser::parse;
    use super::*;

    fn detected(text: &str) -> Detected {
        let mut diagnostics = Diagnostics::default();
        let blocks = parse(&tokenize(text), &Comments::of(text), &mut diagnostics);
        assert!(diagnostics.errors.is_empty(), "{diagnostics:?}");
        detect(&blocks)
    }

    #[test]
    fn signs_of_2016_alone_read_as_2016() {
        let d = detected("Material Red End\nObject Sphere Material RED End");
        assert_eq!(d.dialect, Dialect::Framework2016);
        assert_eq!(d.signs_2016[0].0, 2);
        let d = detected("Object CSG Union Object Sphere End Object Cube End End");
        assert_eq!(d.dialect, Dialect::Framework2016);
    }

    #[test]
    fn signs_of_2020_or_of_both_or_none_read_as_2020() {
        for text in [
            "Light SpotLight End",
            "ObjectGroup End",
            "Object CSG Union Object Sphere End Object Cube End End Light AmbientLight End",
            "Scene ambientLight 1 1 1 End Object Sphere End",
        ] {
            assert_eq!(detected(text).dialect, Dialect::Framework2020, "{text}");
        }
    }
}
