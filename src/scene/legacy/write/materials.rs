//! Material blocks, under names the course readers take as one token.
//!
//! A course material name is one token: no whitespace, not starting with `#` (a
//! comment), not `End` (which closes the block); the 2016 framework upper-cases whole
//! lines, so there names must also differ in more than case. A name that breaks a rule
//! is written with its whitespace as `_` (and a `m_` in front where it starts with `#` or
//! is `End`), made unique with `_2`, `_3`..., and warned about by name.
//!
//! A Material block starts from the reader's default material, so every field is
//! written. Transmission is the extension's `Opacity a` (kt = 1 - a, grey) with
//! `RefractiveIndex n`, which only the 2020 dialect's readers have.

use std::collections::{BTreeMap, HashSet};

use glam::DVec3;

use super::super::convert::Dialect;
use super::numbers::{number, triple};
use super::problem::{Problems, Subject};
use crate::scene::Material;

/// The course name of each scene material, by scene name.
pub type MaterialNames = BTreeMap<String, String>;

/// One-token names for every material, with a warning for each that changes.
pub fn material_names(
    materials: &BTreeMap<String, Material>,
    dialect: Dialect,
    problems: &mut Problems,
) -> MaterialNames {
    let fold = |name: &str| match dialect {
        Dialect::Framework2016 => name.to_uppercase(),
        Dialect::Framework2020 => name.to_owned(),
    };
    // Names that are fine as they are keep them; the others take what is left.
    let mut taken: HashSet<String> = materials
        .keys()
        .filter(|name| is_token_name(name))
        .map(|name| fold(name))
        .collect();
    let mut kept: HashSet<String> = HashSet::new();
    let mut names = MaterialNames::new();
    for name in materials.keys() {
        let folded = fold(name);
        if is_token_name(name) && kept.insert(folded) {
            names.insert(name.clone(), name.clone());
            continue;
        }
        let base = token_name(name);
        let mut written = base.clone();
        let mut n = 2;
        while taken.contains(&fold(&written)) {
            written = format!("{base}_{n}");
            n += 1;
        }
        taken.insert(fold(&written));
        let why = if is_token_name(name) {
            "the 2016 framework upper-cases lines, so its names must differ in more than case"
        } else {
            "a course material name is one word, not a comment and not `End`"
        };
        problems.warn(
            Subject::Material(name.clone()),
            format!("written as `{written}` ({why})"),
        );
        names.insert(name.clone(), written);
    }
    names
}

/// Whether `name` is one token the readers take as a material name.
fn is_token_name(name: &str) -> bool {
    !name.is_empty()
        && !name.contains(char::is_whitespace)
        && !name.starts_with('#')
        && !name.eq_ignore_ascii_case("End")
}

/// `name` with its whitespace as `_`, made a name where it would be a comment or `End`.
fn token_name(name: &str) -> String {
    let joined: String = name.split_whitespace().collect::<Vec<_>>().join("_");
    if joined.is_empty() || joined.starts_with('#') || joined.eq_ignore_ascii_case("End") {
        format!("m_{joined}")
    } else {
        joined
    }
}

/// The Material block of `material`, or nothing (with a refusal) where the dialect
/// cannot say its transmission.
/// A material no object uses is written without what the dialect cannot say, with a
/// warning, instead of being refused.
pub fn material_block(
    scene_name: &str,
    written: &str,
    material: &Material,
    used: bool,
    dialect: Dialect,
    problems: &mut Problems,
) -> String {
    let subject = || Subject::Material(scene_name.to_owned());
    let refuse = |problems: &mut Problems, message: String| {
        if used {
            problems.refuse(subject(), message);
        } else {
            problems.warn(
                subject(),
                format!("no object uses it, so it is written without its transmission: {message}"),
            );
        }
    };
    let mut text = format!("Material {written}\n");
    text.push_str(&format!("  Ambient {}\n", triple(material.ambient)));
    text.push_str(&format!("  Diffuse {}\n", triple(material.diffuse)));
    text.push_str(&format!(
        "  Specular {} {}\n",
        triple(material.specular),
        number(material.shininess)
    ));
    text.push_str(&format!("  Mirror {}\n", triple(material.mirror)));
    let kt = material.transmission;
    let transmits = kt != DVec3::ZERO;
    match dialect {
        Dialect::Framework2016 => {
            if transmits {
                refuse(
                    problems,
                    format!(
                        "it transmits light (transmission {}, ior {}); the 2016 dialect has \
                         no Opacity or RefractiveIndex (use --dialect 2020)",
                        triple(kt),
                        number(material.ior)
                    ),
                );
            } else if material.ior != 1.0 {
                problems.warn(
                    subject(),
                    format!(
                        "ior {} is not written (the 2016 dialect has no RefractiveIndex; \
                         with no transmission it changes nothing)",
                        number(material.ior)
                    ),
                );
            }
        }
        Dialect::Framework2020 => {
            if transmits {
                if kt.x == kt.y && kt.y == kt.z {
                    text.push_str(&format!("  Opacity {}\n", number(opacity(kt.x))));
                } else {
                    refuse(
                        problems,
                        format!(
                            "its transmission {} is coloured; the course's Opacity a says \
                             only a grey one (1 - a)",
                            triple(kt)
                        ),
                    );
                }
            }
            if material.ior != 1.0 {
                text.push_str(&format!("  RefractiveIndex {}\n", number(material.ior)));
            }
        }
    }
    text.push_str("End\n");
    text
}

/// The opacity `a` whose `1 - a` is `kt` exactly where there is one (the importer reads
/// `Opacity a` as kt = 1 - a), else the nearest.
fn opacity(kt: f64) -> f64 {
    let first = 1.0 - kt;
    let mut candidate = first;
    for _ in 0..4 {
        if 1.0 - candidate == kt {
            return candidate;
        }
        candidate = candidate.next_down();
    }
    let mut candidate = first.next_up();
    for _ in 0..4 {
        if 1.0 - candidate == kt {
            return candidate;
        }
        candidate = candidate.next_up();
    }
    first
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_become_single_unique_tokens_with_a_warning_each() {
        let materials: BTreeMap<String, Material> = ["red plastic", "red_plastic", "end", "ok"]
            .into_iter()
            .map(|n| (n.to_owned(), Material::default()))
            .collect();
        let mut problems = Problems::default();
        let names = material_names(&materials, Dialect::Framework2020, &mut problems);
        assert_eq!(names["ok"], "ok");
        assert_eq!(names["red_plastic"], "red_plastic");
        assert_eq!(names["red plastic"], "red_plastic_2");
        assert_eq!(names["end"], "m_end");
        assert_eq!(problems.warnings.len(), 2);
        assert!(problems.warnings[0].message.contains("one word"));
    }

    #[test]
    fn names_that_differ_only_in_case_are_told_apart_in_2016() {
        let materials: BTreeMap<String, Material> = ["Red", "red"]
            .into_iter()
            .map(|n| (n.to_owned(), Material::default()))
            .collect();
        let mut problems = Problems::default();
        let names = material_names(&materials, Dialect::Framework2016, &mut problems);
        assert_eq!(names["Red"], "Red");
        assert_eq!(names["red"], "red_2");
        assert!(problems.warnings[0].message.contains("upper-cases"));
    }

    #[test]
    fn opacity_reads_back_as_the_transmission() {
        // From 0.5 up, 1 - a is exact, so some a gives kt back exactly.
        for kt in [0.9, 0.5, 0.75, 1.0, 0.123_456_789 + 0.5] {
            assert_eq!(1.0 - opacity(kt), kt, "{kt}");
        }
        // Below, 1 - a moves in steps of 1's last place: the nearest is taken.
        for kt in [0.1, 0.3, 1e-3] {
            assert!((1.0 - opacity(kt) - kt).abs() <= f64::EPSILON / 2.0, "{kt}");
        }
    }
}
