//! The keywords of a block body and how a body splits into entries: a keyword and the
//! tokens it takes. Unknown keywords are reported here, once each, and skipped with the
//! numbers after them.

use super::super::error::{Diagnostics, LegacyError};
use super::super::lexer::{Token, block_word, looks_numeric};
use super::super::syntax::{At, Item};
use super::at_token::{at, error};

/// Every keyword that may appear inside a block; each block kind lists the ones it takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Word {
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
    Opacity,
    RefractiveIndex,
    DisableBoundingBox,
    Supersampling,
    Fsaa,
    ScaleResolution,
    RenderNormals,
    Radius,
    Samples,
}

impl Word {
    /// The keyword as the grammar spells it.
    pub(super) fn name(self) -> &'static str {
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
            Word::Opacity => "Opacity",
            Word::RefractiveIndex => "RefractiveIndex",
            Word::DisableBoundingBox => "DisableBoundingBox",
            Word::Supersampling => "Supersampling",
            Word::Fsaa => "FSAA",
            Word::ScaleResolution => "scaleResolution",
            Word::RenderNormals => "renderNormals",
            Word::Radius => "Radius",
            Word::Samples => "Samples",
        }
    }

    /// What follows the keyword, for messages; one word per token.
    pub(super) fn usage(self) -> &'static str {
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
            Word::Opacity => "a",
            Word::RefractiveIndex => "n",
            Word::DisableBoundingBox | Word::Supersampling | Word::RenderNormals => "",
            Word::Fsaa | Word::Samples => "N",
            Word::ScaleResolution => "s",
            Word::Radius => "r",
        }
    }

    /// Whether the token after the keyword is taken whatever it looks like.
    fn takes_name(self) -> bool {
        matches!(self, Word::Filename | Word::Material | Word::Rotate)
    }
}

/// A keyword and the tokens it took.
pub(super) struct Entry<'t, 'a> {
    /// Which keyword.
    pub(super) word: Word,
    /// The keyword's token, as written.
    pub(super) keyword: Token<'a>,
    /// The tokens after it that belong to it.
    pub(super) args: &'t [Token<'a>],
}

impl Entry<'_, '_> {
    fn at(&self) -> At {
        at(&self.keyword)
    }
}

fn item<T>(value: T, entry: &Entry<'_, '_>) -> Item<T> {
    Item {
        value,
        at: entry.at(),
    }
}

/// The items that are there: keywords that are read but dropped (with a warning) are
/// `None`.
pub(super) fn present<T>(items: Vec<Item<Option<T>>>) -> Vec<Item<T>> {
    items
        .into_iter()
        .filter_map(|item| item.value.map(|value| Item { value, at: item.at }))
        .collect()
}

/// Decodes every entry of a block body with `decode_entry`, reporting errors in token
/// order. An unknown keyword is skipped with a warning (with the numbers after it); a
/// block word where a keyword should be is an error (a missing `End`). Returns the
/// decoded items and the keywords that failed (as the grammar spells them).
pub(super) fn decode<T>(
    body: &[Token<'_>],
    words: &[&[Word]],
    block: &Token<'_>,
    errors: &mut Diagnostics,
    decode_entry: fn(&Entry<'_, '_>, &mut Diagnostics) -> Option<T>,
) -> (Vec<Item<T>>, Vec<String>) {
    let mut items = Vec::new();
    let mut broken = Vec::new();
    for entry in entries(body, words) {
        match entry {
            Ok(entry) => match decode_entry(&entry, errors) {
                Some(value) => items.push(item(value, &entry)),
                None => broken.push(entry.word.name().to_owned()),
            },
            Err(token) if block_word(&token).is_some() => {
                errors.push(unknown_keyword(&token, words, block));
            }
            Err(token) => {
                let block_name = block_word(block).unwrap_or(block.text);
                errors.warn(
                    token.line,
                    format!(
                        "unknown keyword `{}` in this {block_name} block: skipped (with the \
                         numbers after it)",
                        token.text
                    ),
                );
            }
        }
    }
    (items, broken)
}

/// Splits a block body into keyword entries, and the tokens that are no keyword of this
/// block (each skipped with the numbers after it).
fn entries<'t, 'a>(
    body: &'t [Token<'a>],
    words: &[&[Word]],
) -> Vec<Result<Entry<'t, 'a>, Token<'a>>> {
    let mut out = Vec::new();
    let mut i = 0;
    while let Some(token) = body.get(i) {
        let word = words
            .iter()
            .copied()
            .flatten()
            .copied()
            .find(|w| token.is(w.name()));
        let mut j = i + 1;
        // A keyword that takes a name, or a block word (from a missing `End`) with its
        // type, takes the next token whatever it looks like.
        let takes_name = match word {
            Some(word) => word.takes_name(),
            None => block_word(token).is_some_and(|w| !matches!(w, "Scene" | "ObjectGroup")),
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
            None => Err(*token),
        });
        i = j;
    }
    out
}

fn unknown_keyword(token: &Token<'_>, words: &[&[Word]], block: &Token<'_>) -> LegacyError {
    let block_name = block_word(block).unwrap_or("this");
    let expected: Vec<&str> = words.iter().copied().flatten().map(|w| w.name()).collect();
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
