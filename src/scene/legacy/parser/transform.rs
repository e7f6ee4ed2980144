//! The transform keywords cameras and objects share: `Translate x y z`, `Rotate X|Y|Z
//! deg`, `Scale s` and `Scale3 sx sy sz` (no scale may be zero).

use glam::DVec3;

use super::super::error::Diagnostics;
use super::super::syntax::{Axis, TransformStep};
use super::at_token::error;
use super::entries::{Entry, Word};
use super::values::{number, numbers, vector};

/// The transform keywords (all a Camera block takes).
pub(super) const TRANSFORM_WORDS: &[Word] =
    &[Word::Translate, Word::Rotate, Word::Scale, Word::Scale3];

/// One transform keyword.
pub(super) fn transform_step(
    entry: &Entry<'_, '_>,
    errors: &mut Diagnostics,
) -> Option<TransformStep> {
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

fn non_zero_scales(entry: &Entry<'_, '_>, values: &[f64], errors: &mut Diagnostics) -> bool {
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

fn rotate(entry: &Entry<'_, '_>, errors: &mut Diagnostics) -> Option<TransformStep> {
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

#[cfg(test)]
mod tests {
    use super::super::super::syntax::Block;
    use super::super::parse_text;
    use super::*;

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
