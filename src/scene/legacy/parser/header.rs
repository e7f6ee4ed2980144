//! A block's header: the type (or name) token right after the block word, the numbers
//! after it, and the body that follows.

use super::super::error::Diagnostics;
use super::super::lexer::{Token, looks_numeric};
use super::at_token::error;

/// A block header: the type (or name) token right after the block word, the numbers after
/// it, and the body. `None`, with an error, when the block is empty.
pub(super) struct Header<'t, 'a> {
    pub(super) kind: Token<'a>,
    pub(super) numbers: &'t [Token<'a>],
    pub(super) body: &'t [Token<'a>],
}

pub(super) fn header<'t, 'a>(
    word: &Token<'a>,
    rest: &'t [Token<'a>],
    needs: &str,
    errors: &mut Diagnostics,
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
pub(super) fn no_numbers(header: &Header<'_, '_>, errors: &mut Diagnostics) -> bool {
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
