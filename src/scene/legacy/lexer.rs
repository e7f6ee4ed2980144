//! Tokens of the legacy format: runs of non-whitespace, each with its line number.
//!
//! Whitespace (spaces, tabs, CR, LF) separates tokens. A token that *starts* with `#`
//! begins a comment that runs to the end of the line; a `#` inside a token is part of it.
//! Line breaks are LF, CR LF, or a lone CR. A leading byte-order mark is skipped.

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
    fn case_insensitive_comparison() {
        let token = Token {
            text: "eNd",
            line: 1,
        };
        assert!(token.is("End"));
        assert!(!token.is("Ends"));
    }
}
