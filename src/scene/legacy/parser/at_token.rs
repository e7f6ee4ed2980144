//! Where a token stands: its place in the file, and an error reported there.

use super::super::error::LegacyError;
use super::super::lexer::Token;
use super::super::syntax::At;

/// The token's line and text, for a block or entry that starts at it.
pub(super) fn at(token: &Token<'_>) -> At {
    At {
        line: token.line,
        token: token.text.to_owned(),
    }
}

/// An error at the token's line, quoting the token.
pub(super) fn error(token: &Token<'_>, message: impl Into<String>) -> LegacyError {
    LegacyError::new(token.line, token.text, message)
}
