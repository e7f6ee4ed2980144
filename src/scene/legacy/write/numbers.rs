//! Numbers as the course readers read them: whole tokens that parse back to the same
//! `f64` (Rust's shortest round-trip form), plain decimals in the usual range and
//! `1e-7` style outside it (both C's `strtod` and raylab's importer read that), never
//! `-0`, `inf` or `NaN` (the scene rules keep those out).

use glam::DVec3;

/// Below this magnitude (and above [`LARGE`]) a number is written with an exponent, so
/// that it stays short.
const SMALL: f64 = 1e-4;
/// See [`SMALL`].
const LARGE: f64 = 1e15;

/// One number as a token that reads back as exactly `x`.
#[must_use]
pub fn number(x: f64) -> String {
    // `+ 0.0` turns -0 into 0.
    let x = x + 0.0;
    if x == 0.0 {
        return "0".to_owned();
    }
    if (SMALL..LARGE).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Three numbers separated by spaces.
#[must_use]
pub fn triple(v: DVec3) -> String {
    format!("{} {} {}", number(v.x), number(v.y), number(v.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly_and_are_whole_tokens() {
        for x in [
            0.1,
            -0.0,
            1.0 / 3.0,
            1e-7,
            -2.5e-300,
            1e300,
            123_456.789,
            f64::MIN_POSITIVE,
            f64::MAX,
        ] {
            let text = number(x);
            assert!(!text.contains(char::is_whitespace) && !text.contains(','));
            assert_eq!(text.parse::<f64>().unwrap(), x + 0.0, "{text}");
        }
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(2.0), "2");
        assert_eq!(number(1e-7), "1e-7");
        assert_eq!(triple(DVec3::new(0.5, -1.0, 0.0)), "0.5 -1 0");
    }
}
