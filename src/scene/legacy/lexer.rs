//! Tokens of the legacy format: runs of non-whitespace, each with its line number.
//!
//! Whitespace (spaces, tabs, CR, LF) separates tokens. A token that *starts* with `#`
//! begins a comment that runs to the end of the line; a `#` inside a token is part of it.
//! Line breaks are LF, CR LF, or a lone CR. A leading byte-order mark is skipped.

use std::collections::HashMap;

/// The block types, as written in files (matched ignoring case).
pub(crate) const BLOCK_WORDS: [&str; 7] = [
    "Scene",
    "Camera",
    "Light",
    "Material",
    "Object",
    "CSG",
    "ObjectGroup",
];

/// The words besides the block words that start commented-out code rather than a name:
/// `End` and the keywords of every block.
const CODE_WORDS: &[&str] = &[
    "End",
    "renderSize",
    "backgroundColour",
    "ambientLight",
    "rayDepth",
    "filename",
    "Translate",
    "Rotate",
    "Scale",
    "Scale3",
    "Colour",
    "Ambient",
    "Diffuse",
    "Specular",
    "Mirror",
    "Location",
    "Direction",
    "Angle",
    "Opacity",
    "RefractiveIndex",
    "DisableBoundingBox",
    "Supersampling",
    "FSAA",
    "scaleResolution",
    "renderNormals",
    "Radius",
    "Samples",
];

/// Whether `word` is a block word, `End` or a keyword of any block (ignoring case).
#[must_use]
pub fn is_grammar_word(word: &str) -> bool {
    BLOCK_WORDS
        .iter()
        .chain(CODE_WORDS)
        .any(|w| word.eq_ignore_ascii_case(w))
}

/// The block word `token` is (`Scene`, `Camera`, ...), if it is one.
pub(crate) fn block_word(token: &Token<'_>) -> Option<&'static str> {
    BLOCK_WORDS.iter().copied().find(|word| token.is(word))
}

/// Whether a token is meant as a number: it starts with a digit, a sign or a point.
pub(crate) fn looks_numeric(text: &str) -> bool {
    text.starts_with(|c: char| c.is_ascii_digit() || matches!(c, '+' | '-' | '.'))
}

/// The longest name taken from a comment, in characters; a longer comment is prose, not
/// a name.
pub const MAX_COMMENT_NAME_CHARS: usize = 60;

/// One token and the 1-based line it is on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token<'a> {
    /// The token's text, exactly as written.
    pub text: &'a str,
    /// 1-based line number.
    pub line: usize,
}

impl Token<'_> {
    /// Whether the token is `word`, ignoring ASCII case (keywords and type names).
    #[must_use]
    pub fn is(&self, word: &str) -> bool {
        self.text.eq_ignore_ascii_case(word)
    }
}

/// Splits `text` into tokens, dropping comments.
#[must_use]
pub fn tokenize(text: &str) -> Vec<Token<'_>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut tokens = Vec::new();
    let mut line = 1;
    let mut in_comment = false;
    let mut start: Option<usize> = None;
    let mut previous_was_cr = false;
    for (index, c) in text.char_indices() {
        let is_break = c == '\n' || c == '\r';
        if c.is_ascii_whitespace() {
            if let Some(s) = start.take() {
                push_token(&mut tokens, &text[s..index], line, &mut in_comment);
            }
            if is_break {
                // CR LF counts once; a lone CR or LF counts as a break of its own.
                if !(c == '\n' && previous_was_cr) {
                    line += 1;
                }
                in_comment = false;
            }
        } else if start.is_none() && !in_comment {
            start = Some(index);
        }
        previous_was_cr = c == '\r';
    }
    if let Some(s) = start {
        push_token(&mut tokens, &text[s..], line, &mut in_comment);
    }
    tokens
}

fn push_token<'a>(tokens: &mut Vec<Token<'a>>, text: &'a str, line: usize, in_comment: &mut bool) {
    if text.starts_with('#') {
        *in_comment = true;
    } else {
        tokens.push(Token { text, line });
    }
}

/// The whole-line comments of a file (lines whose first token starts with `#`), by line,
/// for naming the block that follows.
#[derive(Clone, Debug, Default)]
pub struct Comments<'a> {
    by_line: HashMap<usize, &'a str>,
}

impl<'a> Comments<'a> {
    /// Collects the whole-line comments of `text`, with the lines counted as
    /// [`tokenize`] counts them (LF, CR LF or a lone CR).
    #[must_use]
    pub fn of(text: &'a str) -> Self {
        let mut rest = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut by_line = HashMap::new();
        let mut line = 1;
        loop {
            let end = rest.find(['\n', '\r']).unwrap_or(rest.len());
            let content = rest[..end].trim_matches(|c: char| c.is_ascii_whitespace());
            if let Some(comment) = content.strip_prefix('#') {
                by_line.insert(line, comment);
            }
            if end == rest.len() {
                break;
            }
            let skip = if rest[end..].starts_with("\r\n") {
                2
            } else {
                1
            };
            rest = &rest[end + skip..];
            line += 1;
        }
        Self { by_line }
    }

    /// The name a comment on the line right before `line` gives the block starting
    /// there (`# Snowman's body` names it "Snowman's body"): `None` when there is no
    /// such comment, it is empty or too long, or it is commented-out code. A `/`
    /// (the separator of tree paths) becomes `-`.
    #[must_use]
    pub fn name_before(&self, line: usize) -> Option<String> {
        let comment = self.by_line.get(&line.checked_sub(1)?)?;
        let text = comment
            .trim_start_matches('#')
            .trim_matches(|c: char| c.is_ascii_whitespace());
        let first_word = text.split_ascii_whitespace().next()?;
        let is_code = is_grammar_word(first_word);
        if is_code || text.chars().count() > MAX_COMMENT_NAME_CHARS {
            return None;
        }
        Some(text.replace('/', "-"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn texts(source: &str) -> Vec<(&str, usize)> {
        tokenize(source).iter().map(|t| (t.text, t.line)).collect()
    }

    #[test]
    fn splits_on_whitespace_and_counts_lines() {
        assert_eq!(
            texts("Scene\n\trenderSize  4 3\r\nEnd"),
            [
                ("Scene", 1),
                ("renderSize", 2),
                ("4", 2),
                ("3", 2),
                ("End", 3)
            ]
        );
    }

    #[test]
    fn hash_at_token_start_comments_out_the_rest_of_the_line() {
        assert_eq!(
            texts("# whole line\nColour 1 #0 0\n#tight comment\nEnd"),
            [("Colour", 2), ("1", 2), ("End", 4)]
        );
    }

    #[test]
    fn hash_inside_a_token_is_part_of_it() {
        assert_eq!(
            texts("Material red#1 # note"),
            [("Material", 1), ("red#1", 1)]
        );
    }

    #[test]
    fn lone_cr_is_a_line_break_and_bom_is_skipped() {
        assert_eq!(texts("\u{feff}a\rb\r\rc"), [("a", 1), ("b", 2), ("c", 4)]);
    }

    #[test]
    fn a_whole_line_comment_right_before_a_block_names_it() {
        let comments = Comments::of("# Snowman's body\r\nObject Sphere End\n\n## base ##\nx\n");
        assert_eq!(comments.name_before(2).as_deref(), Some("Snowman's body"));
        assert_eq!(comments.name_before(5).as_deref(), Some("base ##"));
        // A blank line between the comment and the block breaks the link.
        assert_eq!(comments.name_before(3), None);
        assert_eq!(comments.name_before(1), None);
    }

    #[test]
    fn commented_out_code_and_trailing_comments_name_nothing() {
        let comments =
            Comments::of("#Translate 0 1 0\nObject Cube End # trailing\nObject Cone\n#\nEnd");
        assert_eq!(comments.name_before(2), None);
        assert_eq!(comments.name_before(3), None);
        assert_eq!(comments.name_before(5), None);
    }

    #[test]
    fn case_insensitive_comparison() {
        let token = Token {
            text: "eNd",
            line: 1,
        };
        assert!(token.is("End"));
        assert!(!token.is("Ends"));
    }
}
