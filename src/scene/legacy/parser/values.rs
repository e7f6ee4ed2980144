//! The arguments of an entry: numbers as whole tokens, vectors, colours (never
//! negative), whole numbers in a range, and single names. Each check reports its error
//! at the token that holds the value.

use glam::DVec3;

use super::super::error::Diagnostics;
use super::super::lexer::Token;
use super::at_token::error;
use super::entries::Entry;

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

/// One token as a number, or an error at it.
pub(super) fn number(token: &Token<'_>, errors: &mut Diagnostics) -> Option<f64> {
    parse_number(token.text)
        .map_err(|message| errors.push(error(token, message)))
        .ok()
}

/// Checks the entry has as many arguments as its usage names and parses them all as
/// numbers.
pub(super) fn numbers(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<Vec<f64>> {
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

/// Three numbers as a vector.
pub(super) fn vector(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<DVec3> {
    numbers(entry, errors).map(|v| DVec3::new(v[0], v[1], v[2]))
}

/// A colour: three numbers, none negative.
pub(super) fn colour(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<DVec3> {
    let value = vector(entry, errors)?;
    non_negative(entry, &value.to_array(), errors).then_some(value)
}

/// Whether none of `values` (the entry's first arguments) is negative; an error at each
/// one that is.
pub(super) fn non_negative(
    entry: &Entry<'_, '_>,
    values: &[f64],
    errors: &mut Diagnostics,
) -> bool {
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
pub(super) fn whole(
    token: &Token<'_>,
    value: f64,
    range: std::ops::RangeInclusive<u32>,
    what: &str,
    errors: &mut Diagnostics,
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

/// A whole number of at least 1 (`Samples N`, `FSAA N`): above `max` it is capped, with
/// a warning naming the token, as raylab takes at most `max` `what`.
pub(super) fn capped_count(
    token: &Token<'_>,
    value: f64,
    max: u32,
    what: &str,
    errors: &mut Diagnostics,
) -> Option<u32> {
    if !(value.fract() == 0.0 && value >= 1.0) {
        errors.push(error(token, "a count must be a whole number, 1 or more"));
        return None;
    }
    if value > f64::from(max) {
        errors.warn(
            token.line,
            format!(
                "`{}`: raylab takes at most {max} {what}, so it imports {max}",
                token.text
            ),
        );
        return Some(max);
    }
    // Whole and in 1..=max, so the conversion is exact.
    Some(value as u32)
}

/// The single name token of `Material NAME` or `filename NAME`.
pub(super) fn name(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<String> {
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
