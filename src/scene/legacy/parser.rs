//! Tokens to typed blocks, collecting every error on the way.
//!
//! A block is the tokens up to the next `End`. Inside a block, a keyword starts an entry
//! and takes the tokens after it that look like numbers (they start with a digit, a sign
//! or a point); keywords that take a name (`Material`, `filename`, and the axis of
//! `Rotate`) take the next token whatever it is. Anything else where a keyword should be
//! is an unknown keyword, reported and skipped together with the numbers after it, so one
//! mistake gives one error. Numbers are whole tokens: `1,0` is a bad number, not `1`.
//!
//! Values the scene format cannot hold (negative colours, zero scales, a spot angle over
//! 90 degrees...) are errors here too, at the token that holds them.

use glam::DVec3;

use super::error::LegacyError;
use super::lexer::Token;
use super::syntax::{
    At, Axis, Block, Item, LightKind, LightSetting, ObjectKind, ObjectSetting, ParsedBlock,
    SceneSetting, SurfaceEdit, TransformStep,
};
use crate::scene::Shape;
use crate::scene::validate::{MAX_DEPTH, MAX_IMAGE_SIDE};

/// The block types, as written in files (matched ignoring case).
const BLOCK_WORDS: [&str; 5] = ["Scene", "Camera", "Light", "Material", "Object"];

/// Every keyword that may appear inside a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Word {
    RenderSize,
    BackgroundColour,
    AmbientLight,
    RayDepth,
    Filename,
    Translate,
    Rotate,
    Scale,
    Scale3,
    Colour,
    Ambient,
    Diffuse,
    Specular,
    Mirror,
    Location,
    Direction,
    Angle,
    Material,
}

const SCENE_WORDS: &[Word] = &[
    Word::RenderSize,
    Word::BackgroundColour,
    Word::AmbientLight,
    Word::RayDepth,
    Word::Filename,
];
const TRANSFORM_WORDS: &[Word] = &[Word::Translate, Word::Rotate, Word::Scale, Word::Scale3];
const LIGHT_WORDS: &[Word] = &[Word::Colour, Word::Location, Word::Direction, Word::Angle];
const MATERIAL_WORDS: &[Word] = &[
    Word::Colour,
    Word::Ambient,
    Word::Diffuse,
    Word::Specular,
    Word::Mirror,
];
const OBJECT_WORDS: &[Word] = &[
    Word::Material,
    Word::Colour,
    Word::Ambient,
    Word::Diffuse,
    Word::Specular,
    Word::Mirror,
    Word::Translate,
    Word::Rotate,
    Word::Scale,
    Word::Scale3,
];

impl Word {
    /// The keyword as the grammar spells it.
    fn name(self) -> &'static str {
        match self {
            Word::RenderSize => "renderSize",
            Word::BackgroundColour => "backgroundColour",
            Word::AmbientLight => "ambientLight",
            Word::RayDepth => "rayDepth",
            Word::Filename => "filename",
            Word::Translate => "Translate",
            Word::Rotate => "Rotate",
            Word::Scale => "Scale",
            Word::Scale3 => "Scale3",
            Word::Colour => "Colour",
            Word::Ambient => "Ambient",
            Word::Diffuse => "Diffuse",
            Word::Specular => "Specular",
            Word::Mirror => "Mirror",
            Word::Location => "Location",
            Word::Direction => "Direction",
            Word::Angle => "Angle",
            Word::Material => "Material",
        }
    }

    /// What follows the keyword, for messages; one word per token.
    fn usage(self) -> &'static str {
        match self {
            Word::RenderSize => "W H",
            Word::BackgroundColour
            | Word::AmbientLight
            | Word::Colour
            | Word::Ambient
            | Word::Diffuse
            | Word::Mirror => "R G B",
            Word::RayDepth => "N",
            Word::Filename | Word::Material => "NAME",
            Word::Translate | Word::Location | Word::Direction => "x y z",
            Word::Rotate => "X|Y|Z deg",
            Word::Scale => "s",
            Word::Scale3 => "sx sy sz",
            Word::Specular => "R G B EXP",
            Word::Angle => "deg",
        }
    }

    /// Whether the token after the keyword is taken whatever it looks like.
    fn takes_name(self) -> bool {
        matches!(self, Word::Filename | Word::Material | Word::Rotate)
    }
}

/// A keyword and the tokens it took.
struct Entry<'t, 'a> {
    word: Word,
    keyword: Token<'a>,
    args: &'t [Token<'a>],
}

impl Entry<'_, '_> {
    fn at(&self) -> At {
        at(&self.keyword)
    }
}

fn at(token: &Token<'_>) -> At {
    At {
        line: token.line,
        token: token.text.to_owned(),
    }
}

fn error(token: &Token<'_>, message: impl Into<String>) -> LegacyError {
    LegacyError::new(token.line, token.text, message)
}

/// Parses the whole token stream into blocks. Blocks with errors in their header are
/// left out; entries with errors are left out of their block. Every error is pushed.
pub fn parse(tokens: &[Token<'_>], errors: &mut Vec<LegacyError>) -> Vec<ParsedBlock> {
    let mut blocks = Vec::new();
    let mut rest = tokens;
    while let Some(first) = rest.first() {
        match rest.iter().position(|t| t.is("End")) {
            Some(0) => {
                errors.push(error(first, "`End` with no block before it"));
                rest = &rest[1..];
            }
            Some(end) => {
                blocks.extend(parse_block(&rest[..end], errors));
                rest = &rest[end + 1..];
            }
            None => {
                if let Some(word) = block_word(first) {
                    errors.push(error(
                        first,
                        format!("the {word} block has no `End` (unexpected end of file)"),
                    ));
                    blocks.extend(parse_block(rest, errors));
                } else {
                    errors.push(error(
                        first,
                        "unexpected end of file: tokens after the last `End`",
                    ));
                }
                break;
            }
        }
    }
    blocks
}

fn block_word(token: &Token<'_>) -> Option<&'static str> {
    BLOCK_WORDS.iter().copied().find(|word| token.is(word))
}

/// One block: its tokens without the `End`; never empty.
fn parse_block(tokens: &[Token<'_>], errors: &mut Vec<LegacyError>) -> Option<ParsedBlock> {
    let (first, rest) = tokens.split_first()?;
    match block_word(first) {
        Some("Scene") => {
            let (settings, _) = decode(rest, SCENE_WORDS, first, errors, scene_setting);
            Some(ParsedBlock {
                block: Block::Scene(settings),
                at: at(first),
            })
        }
        Some("Camera") => parse_camera(first, rest, errors),
        Some("Light") => parse_light(first, rest, errors),
        Some("Material") => parse_material(first, rest, errors),
        Some("Object") => parse_object(first, rest, errors),
        _ => {
            errors.push(error(
                first,
                "unknown block type (expected Scene, Camera, Light, Material or Object)",
            ));
            None
        }
    }
}

/// A block header: the type (or name) token right after the block word, the numbers after
/// it, and the body. `None`, with an error, when the block is empty.
struct Header<'t, 'a> {
    kind: Token<'a>,
    numbers: &'t [Token<'a>],
    body: &'t [Token<'a>],
}

fn header<'t, 'a>(
    word: &Token<'a>,
    rest: &'t [Token<'a>],
    needs: &str,
    errors: &mut Vec<LegacyError>,
) -> Option<Header<'t, 'a>> {
    let Some((kind, after)) = rest.split_first() else {
        errors.push(error(word, format!("the block needs {needs}")));
        return None;
    };
    let count = after.iter().take_while(|t| looks_numeric(t.text)).count();
    Some(Header {
        kind: *kind,
        numbers: &after[..count],
        body: &after[count..],
    })
}

/// Reports numbers after a header that takes none.
fn no_numbers(header: &Header<'_, '_>, errors: &mut Vec<LegacyError>) -> bool {
    if let Some(first) = header.numbers.first() {
        errors.push(error(
            first,
            format!(
                "`{}` takes no numbers, found {}",
                header.kind.text,
                header.numbers.len()
            ),
        ));
        return false;
    }
    true
}

fn parse_camera(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Vec<LegacyError>,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a camera type: `PinholeCamera F`", errors)?;
    let known = header.kind.is("PinholeCamera");
    if !known {
        errors.push(error(
            &header.kind,
            "unknown camera type (expected PinholeCamera F)",
        ));
    }
    let focal_length = if known {
        focal_length(&header, errors)
    } else {
        None
    };
    let (transforms, _) = decode(header.body, TRANSFORM_WORDS, word, errors, transform_step);
    Some(ParsedBlock {
        block: Block::Camera {
            focal_length: focal_length?,
            transforms,
        },
        at: at(&header.kind),
    })
}

fn focal_length(header: &Header<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<f64> {
    let [token] = header.numbers else {
        errors.push(error(
            &header.kind,
            format!(
                "`PinholeCamera` takes F, the focal length (1 number), found {}",
                header.numbers.len()
            ),
        ));
        return None;
    };
    let value = number(token, errors)?;
    if value <= 0.0 {
        errors.push(error(token, "the focal length must be positive"));
        return None;
    }
    Some(value)
}

fn parse_light(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Vec<LegacyError>,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a light type, such as `PointLight`", errors)?;
    let kind = [
        ("AmbientLight", LightKind::Ambient),
        ("PointLight", LightKind::Point),
        ("DirectionalLight", LightKind::Directional),
        ("SpotLight", LightKind::Spot),
    ]
    .into_iter()
    .find(|(name, _)| header.kind.is(name))
    .map(|(_, kind)| kind);
    if kind.is_none() {
        errors.push(error(
            &header.kind,
            "unknown light type (expected AmbientLight, PointLight, DirectionalLight or SpotLight)",
        ));
    }
    let numbers_ok = no_numbers(&header, errors);
    let (settings, broken) = decode(header.body, LIGHT_WORDS, word, errors, light_setting);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Light {
            kind: kind?,
            settings,
            broken,
        },
        at: at(&header.kind),
    })
}

fn parse_material(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Vec<LegacyError>,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a name: `Material NAME`", errors)?;
    let numbers_ok = no_numbers(&header, errors);
    let (edits, _) = decode(header.body, MATERIAL_WORDS, word, errors, surface_edit);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Material {
            name: header.kind.text.to_owned(),
            edits,
        },
        at: at(&header.kind),
    })
}

fn parse_object(
    word: &Token<'_>,
    rest: &[Token<'_>],
    errors: &mut Vec<LegacyError>,
) -> Option<ParsedBlock> {
    let header = header(word, rest, "a shape, such as `Sphere`", errors)?;
    let kind = Shape::ALL
        .into_iter()
        .find(|shape| header.kind.is(shape.name()))
        .map(ObjectKind::Shape)
        .or_else(|| {
            header
                .kind
                .is("Octahedron")
                .then_some(ObjectKind::Octahedron)
        });
    if kind.is_none() {
        errors.push(error(
            &header.kind,
            "unknown object type (expected Sphere, Plane, Cube, Cylinder or Cone)",
        ));
    }
    let numbers_ok = no_numbers(&header, errors);
    let (settings, _) = decode(header.body, OBJECT_WORDS, word, errors, object_setting);
    numbers_ok.then_some(())?;
    Some(ParsedBlock {
        block: Block::Object {
            kind: kind?,
            settings,
        },
        at: at(&header.kind),
    })
}

fn item<T>(value: T, entry: &Entry<'_, '_>) -> Item<T> {
    Item {
        value,
        at: entry.at(),
    }
}

/// Decodes every entry of a block body with `decode_entry`, reporting errors in token
/// order. Returns the decoded items and the keywords that failed (as the grammar spells
/// them).
fn decode<T>(
    body: &[Token<'_>],
    words: &[Word],
    block: &Token<'_>,
    errors: &mut Vec<LegacyError>,
    decode_entry: fn(&Entry<'_, '_>, &mut Vec<LegacyError>) -> Option<T>,
) -> (Vec<Item<T>>, Vec<String>) {
    let mut items = Vec::new();
    let mut broken = Vec::new();
    for entry in entries(body, words, block) {
        match entry {
            Ok(entry) => match decode_entry(&entry, errors) {
                Some(value) => items.push(item(value, &entry)),
                None => broken.push(entry.word.name().to_owned()),
            },
            Err(error) => errors.push(error),
        }
    }
    (items, broken)
}

/// Splits a block body into keyword entries, and errors for unknown keywords (which are
/// skipped with the numbers after them).
fn entries<'t, 'a>(
    body: &'t [Token<'a>],
    words: &[Word],
    block: &Token<'_>,
) -> Vec<Result<Entry<'t, 'a>, LegacyError>> {
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(token) = body.get(i) {
        let word = words.iter().copied().find(|w| token.is(w.name()));
        let mut j = i + 1;
        // A keyword that takes a name, or a block word (from a missing `End`) with its
        // type, takes the next token whatever it looks like.
        let takes_name = match word {
            Some(word) => word.takes_name(),
            None => block_word(token).is_some_and(|w| w != "Scene"),
        };
        if takes_name && j < body.len() {
            j += 1;
        }
        while body.get(j).is_some_and(|t| looks_numeric(t.text)) {
            j += 1;
        }
        out.push(match word {
            Some(word) => Ok(Entry {
                word,
                keyword: *token,
                args: &body[i + 1..j],
            }),
            None => Err(unknown_keyword(token, words, block)),
        });
        i = j;
    }
    out
}

fn unknown_keyword(token: &Token<'_>, words: &[Word], block: &Token<'_>) -> LegacyError {
    let block_name = block_word(block).unwrap_or("this");
    let expected: Vec<&str> = words.iter().map(|w| w.name()).collect();
    let mut message = format!(
        "unknown keyword in this {block_name} block (expected {})",
        expected.join(", ")
    );
    if block_word(token).is_some() {
        message.push_str(&format!(
            "; is the `End` of the {block_name} block at line {} missing?",
            block.line
        ));
    }
    error(token, message)
}

/// Whether a token is meant as a number: it starts with a digit, a sign or a point.
fn looks_numeric(text: &str) -> bool {
    text.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.'))
}

/// A whole token as a finite number: `1`, `-3`, `1.`, `.5`, `1e-3`; not `1,0`, `inf`, `0x1`.
fn parse_number(text: &str) -> Result<f64, &'static str> {
    let plain = text
        .chars()
        .all(|c| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'));
    let has_digit = text.chars().any(|c| c.is_ascii_digit());
    let not_a_number = "not a number (numbers are whole tokens such as 2, -0.5, .5, 1. or 1e-3)";
    if !plain || !has_digit {
        return Err(not_a_number);
    }
    match text.parse::<f64>() {
        Ok(value) if value.is_finite() => Ok(value),
        Ok(_) => Err("number out of range"),
        Err(_) => Err(not_a_number),
    }
}

fn number(token: &Token<'_>, errors: &mut Vec<LegacyError>) -> Option<f64> {
    parse_number(token.text)
        .map_err(|message| errors.push(error(token, message)))
        .ok()
}

/// Checks the entry has `count` arguments and parses them all as numbers.
fn numbers(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<Vec<f64>> {
    let usage = entry.word.usage();
    let count = usage.split_whitespace().count();
    if entry.args.len() != count {
        let plural = if count == 1 { "" } else { "s" };
        errors.push(error(
            &entry.keyword,
            format!(
                "`{}` takes {usage} ({count} number{plural}), found {}",
                entry.keyword.text,
                entry.args.len()
            ),
        ));
        return None;
    }
    let values: Vec<Option<f64>> = entry.args.iter().map(|t| number(t, errors)).collect();
    values.into_iter().collect()
}

fn vector(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<DVec3> {
    numbers(entry, errors).map(|v| DVec3::new(v[0], v[1], v[2]))
}

/// A colour: three numbers, none negative.
fn colour(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<DVec3> {
    let value = vector(entry, errors)?;
    non_negative(entry, &value.to_array(), errors).then_some(value)
}

fn non_negative(entry: &Entry<'_, '_>, values: &[f64], errors: &mut Vec<LegacyError>) -> bool {
    let mut ok = true;
    for (value, token) in values.iter().zip(entry.args) {
        if *value < 0.0 {
            errors.push(error(token, "colours cannot be negative"));
            ok = false;
        }
    }
    ok
}

/// A whole number in `range`, as `u32`.
fn whole(
    token: &Token<'_>,
    value: f64,
    range: std::ops::RangeInclusive<u32>,
    what: &str,
    errors: &mut Vec<LegacyError>,
) -> Option<u32> {
    let in_range = value.fract() == 0.0
        && value >= f64::from(*range.start())
        && value <= f64::from(*range.end());
    if !in_range {
        errors.push(error(
            token,
            format!(
                "{what} must be a whole number from {} to {}",
                range.start(),
                range.end()
            ),
        ));
        return None;
    }
    // In range and whole, so the conversion is exact.
    Some(value as u32)
}

/// The single name token of `Material NAME` or `filename NAME`.
fn name(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<String> {
    if let [token] = entry.args {
        return Some(token.text.to_owned());
    }
    errors.push(error(
        &entry.keyword,
        format!(
            "`{}` takes NAME (one token), found {} tokens",
            entry.keyword.text,
            entry.args.len()
        ),
    ));
    None
}

fn scene_setting(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<SceneSetting> {
    match entry.word {
        Word::RenderSize => {
            let v = numbers(entry, errors)?;
            let side = |i: usize, errors: &mut Vec<LegacyError>| {
                whole(
                    &entry.args[i],
                    v[i],
                    1..=MAX_IMAGE_SIDE,
                    "an image side",
                    errors,
                )
            };
            let width = side(0, errors);
            let height = side(1, errors);
            Some(SceneSetting::RenderSize {
                width: width?,
                height: height?,
            })
        }
        Word::BackgroundColour => colour(entry, errors).map(SceneSetting::Background),
        Word::AmbientLight => colour(entry, errors).map(SceneSetting::AmbientLight),
        Word::RayDepth => {
            let v = numbers(entry, errors)?;
            whole(&entry.args[0], v[0], 0..=MAX_DEPTH, "the ray depth", errors)
                .map(SceneSetting::RayDepth)
        }
        _ => name(entry, errors).map(SceneSetting::Filename),
    }
}

fn transform_step(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<TransformStep> {
    match entry.word {
        Word::Translate => vector(entry, errors).map(TransformStep::Translate),
        Word::Rotate => rotate(entry, errors),
        Word::Scale => {
            let v = numbers(entry, errors)?;
            non_zero_scales(entry, &v, errors).then_some(TransformStep::Scale(v[0]))
        }
        _ => {
            let v = numbers(entry, errors)?;
            non_zero_scales(entry, &v, errors)
                .then_some(TransformStep::Scale3(DVec3::new(v[0], v[1], v[2])))
        }
    }
}

fn non_zero_scales(entry: &Entry<'_, '_>, values: &[f64], errors: &mut Vec<LegacyError>) -> bool {
    let mut ok = true;
    for (value, token) in values.iter().zip(entry.args) {
        if *value == 0.0 {
            errors.push(error(
                token,
                "a scale of zero flattens the object (the transform would be singular)",
            ));
            ok = false;
        }
    }
    ok
}

fn rotate(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<TransformStep> {
    let [axis_token, angle_token] = entry.args else {
        errors.push(error(
            &entry.keyword,
            format!(
                "`{}` takes X|Y|Z deg (an axis and a number), found {} tokens",
                entry.keyword.text,
                entry.args.len()
            ),
        ));
        return None;
    };
    let axis = [("X", Axis::X), ("Y", Axis::Y), ("Z", Axis::Z)]
        .into_iter()
        .find(|(name, _)| axis_token.is(name))
        .map(|(_, axis)| axis);
    if axis.is_none() {
        errors.push(error(axis_token, "unknown axis (expected X, Y or Z)"));
    }
    let angle_deg = number(angle_token, errors);
    Some(TransformStep::Rotate {
        axis: axis?,
        angle_deg: angle_deg?,
    })
}

fn light_setting(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<LightSetting> {
    match entry.word {
        Word::Colour => colour(entry, errors).map(LightSetting::Colour),
        Word::Location => vector(entry, errors).map(LightSetting::Location),
        Word::Direction => {
            let direction = vector(entry, errors)?;
            if !direction.length_squared().is_normal() {
                errors.push(error(
                    &entry.keyword,
                    "the direction is zero (or too short to give a direction)",
                ));
                return None;
            }
            Some(LightSetting::Direction(direction))
        }
        _ => {
            let v = numbers(entry, errors)?;
            if !(v[0] > 0.0 && v[0] <= 90.0) {
                errors.push(error(
                    &entry.args[0],
                    "a spot light's half-angle must be more than 0 and at most 90 degrees",
                ));
                return None;
            }
            Some(LightSetting::Angle(v[0]))
        }
    }
}

fn surface_edit(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<SurfaceEdit> {
    match entry.word {
        Word::Colour => colour(entry, errors).map(SurfaceEdit::Colour),
        Word::Ambient => colour(entry, errors).map(SurfaceEdit::Ambient),
        Word::Diffuse => colour(entry, errors).map(SurfaceEdit::Diffuse),
        Word::Mirror => colour(entry, errors).map(SurfaceEdit::Mirror),
        _ => {
            let v = numbers(entry, errors)?;
            let mut ok = non_negative(entry, &v[..3], errors);
            if v[3] <= 0.0 {
                errors.push(error(&entry.args[3], "the Phong exponent must be positive"));
                ok = false;
            }
            ok.then_some(SurfaceEdit::Specular {
                colour: DVec3::new(v[0], v[1], v[2]),
                exponent: v[3],
            })
        }
    }
}

fn object_setting(entry: &Entry<'_, '_>, errors: &mut Vec<LegacyError>) -> Option<ObjectSetting> {
    match entry.word {
        Word::Material => name(entry, errors).map(ObjectSetting::Material),
        Word::Translate | Word::Rotate | Word::Scale | Word::Scale3 => {
            transform_step(entry, errors).map(ObjectSetting::Transform)
        }
        _ => surface_edit(entry, errors).map(ObjectSetting::Surface),
    }
}

#[cfg(test)]
mod tests {
    use super::super::lexer::tokenize;
    use super::*;

    fn parse_text(text: &str) -> (Vec<ParsedBlock>, Vec<LegacyError>) {
        let mut errors = Vec::new();
        let blocks = parse(&tokenize(text), &mut errors);
        (blocks, errors)
    }

    #[test]
    fn numbers_are_whole_tokens() {
        for (text, value) in [
            ("1.", 1.0),
            (".5", 0.5),
            ("-3", -3.0),
            ("1e-3", 1e-3),
            ("+2", 2.0),
        ] {
            assert_eq!(parse_number(text), Ok(value), "{text}");
        }
        for text in ["1,0", "inf", "NaN", ".", "-", "0x10", "1e999", "2..", "1e"] {
            assert!(parse_number(text).is_err(), "{text}");
        }
    }

    #[test]
    fn keywords_are_case_insensitive_and_names_are_not() {
        let (blocks, errors) = parse_text("mATERIAL Red cOLOUR 1 0 0 eND");
        assert!(errors.is_empty(), "{errors:?}");
        let Block::Material { name, edits } = &blocks[0].block else {
            panic!("{blocks:?}");
        };
        assert_eq!(name, "Red");
        assert_eq!(edits[0].value, SurfaceEdit::Colour(DVec3::X));
    }

    #[test]
    fn wrong_count_then_unknown_keyword_are_two_separate_errors() {
        let (_, mut errors) = parse_text("Material m\n Colour 1 0\n Shiny 3\nEnd");
        errors.sort_by_key(|e| e.line);
        let summary: Vec<(usize, &str)> =
            errors.iter().map(|e| (e.line, e.token.as_str())).collect();
        assert_eq!(summary, [(2, "Colour"), (3, "Shiny")]);
    }

    #[test]
    fn block_word_inside_a_block_hints_at_a_missing_end() {
        let (_, errors) = parse_text("Object Sphere\n Translate 0 0 1\nObject Cube\nEnd");
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert_eq!((errors[0].line, errors[0].token.as_str()), (3, "Object"));
        assert!(
            errors[0].message.contains("line 1 missing"),
            "{}",
            errors[0]
        );
    }

    #[test]
    fn rotate_takes_an_axis_and_a_number() {
        let (blocks, errors) = parse_text("Camera PinholeCamera 2 rotate y -90 End");
        assert!(errors.is_empty(), "{errors:?}");
        let Block::Camera { transforms, .. } = &blocks[0].block else {
            panic!("{blocks:?}");
        };
        assert_eq!(
            transforms[0].value,
            TransformStep::Rotate {
                axis: Axis::Y,
                angle_deg: -90.0
            }
        );
        let (_, errors) = parse_text("Camera PinholeCamera 2 Rotate W 9 End");
        assert_eq!(errors[0].token, "W");
    }
}
