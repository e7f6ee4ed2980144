//! Object placement: translate / rotate / scale, or a general affine matrix, and the way
//! back from a matrix to the nearest (or an exact) placement.
//!
//! In a file the usual form is an unnamed struct `(translate: .., rotate_deg: .., scale: ..)`
//! and the general form is `Matrix(((m00, m01, m02, m03), (..), (..)))`, the rows of the
//! 3x4 object-to-world matrix. Serde cannot derive a type where one variant has no name,
//! so (de)serialisation is written out here.

use std::fmt;

use glam::{DAffine3, DMat3, DVec3};
use serde::de::{self, MapAccess, SeqAccess, Visitor};
use serde::ser::SerializeStruct;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// Rows of a 3x4 object-to-world matrix.
pub type MatrixRows = [[f64; 4]; 3];

/// Where an object sits in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transform {
    /// Scale, then rotate about X, Y, Z (in that order), then translate.
    Trs(Trs),
    /// A general affine object-to-world matrix, as rows of its top 3x4 part.
    Matrix(MatrixRows),
}

impl Default for Transform {
    fn default() -> Self {
        Transform::Trs(Trs::default())
    }
}

/// Translate / rotate / scale, applied as `T * Rz * Ry * Rx * S`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trs {
    /// Translation in world units.
    pub translate: DVec3,
    /// Euler angles in degrees: about X first, then Y, then Z.
    pub rotate_deg: DVec3,
    /// Scale along the object's axes.
    pub scale: DVec3,
}

impl Default for Trs {
    fn default() -> Self {
        Self {
            translate: DVec3::ZERO,
            rotate_deg: DVec3::ZERO,
            scale: DVec3::ONE,
        }
    }
}

impl Trs {
    /// The nearest translate / rotate / scale to an affine matrix (exact without shear);
    /// the translation alone where the matrix has no rotation and scale to read.
    #[must_use]
    pub fn nearest(affine: &DAffine3) -> Trs {
        let (scale, rotation, translate) = affine.to_scale_rotation_translation();
        // Trs applies Rz * Ry * Rx: glam's ZYX order returns (z, y, x).
        let (z, y, x) = rotation.to_euler(glam::EulerRot::ZYX);
        let trs = Trs {
            translate,
            rotate_deg: DVec3::new(x.to_degrees(), y.to_degrees(), z.to_degrees()),
            scale,
        };
        if trs.scale.is_finite()
            && trs.rotate_deg.is_finite()
            && trs.scale.min_element().abs() > 0.0
        {
            trs
        } else {
            Trs {
                translate,
                ..Trs::default()
            }
        }
    }

    /// The object-to-world matrix.
    #[must_use]
    pub fn world_from_object(&self) -> DAffine3 {
        let (sx, cx) = sin_cos_deg(self.rotate_deg.x);
        let (sy, cy) = sin_cos_deg(self.rotate_deg.y);
        let (sz, cz) = sin_cos_deg(self.rotate_deg.z);
        let rx = DMat3::from_cols(DVec3::X, DVec3::new(0.0, cx, sx), DVec3::new(0.0, -sx, cx));
        let ry = DMat3::from_cols(DVec3::new(cy, 0.0, -sy), DVec3::Y, DVec3::new(sy, 0.0, cy));
        let rz = DMat3::from_cols(DVec3::new(cz, sz, 0.0), DVec3::new(-sz, cz, 0.0), DVec3::Z);
        let rotation = rz * ry * rx;
        DAffine3 {
            matrix3: rotation * DMat3::from_diagonal(self.scale),
            translation: self.translate,
        }
    }
}

/// Sine and cosine of an angle in degrees, exact at multiples of 90 degrees, so that a
/// floor turned by -90 has a normal of exactly +y and `Rotate X 180` turns +Y into exactly
/// -Y. The angle is first reduced with `%`, which is exact, so a large angle keeps its
/// precision and a tiny negative one stays tiny (reducing to [0, 360) instead would round
/// -1e-15 up to 360).
#[must_use]
pub fn sin_cos_deg(degrees: f64) -> (f64, f64) {
    let reduced = degrees % 360.0;
    if reduced % 90.0 == 0.0 {
        // A whole number from -3 to 3, so the conversion is exact.
        match ((reduced / 90.0) as i32).rem_euclid(4) {
            0 => (0.0, 1.0),
            1 => (1.0, 0.0),
            2 => (0.0, -1.0),
            _ => (-1.0, 0.0),
        }
    } else {
        reduced.to_radians().sin_cos()
    }
}

impl Transform {
    /// A placement as translate / rotate / scale where that holds it exactly (to
    /// rounding), else as a matrix (a shear).
    #[must_use]
    pub fn from_affine(affine: &DAffine3) -> Transform {
        let trs = Trs::nearest(affine);
        let again = trs.world_from_object();
        let tolerance = 1e-9 * (1.0 + affine.translation.abs().max_element());
        if again.abs_diff_eq(*affine, tolerance) {
            Transform::Trs(trs)
        } else {
            Transform::Matrix(rows_from_affine(affine))
        }
    }

    /// The object-to-world matrix.
    #[must_use]
    pub fn world_from_object(&self) -> DAffine3 {
        match self {
            Transform::Trs(trs) => trs.world_from_object(),
            Transform::Matrix(rows) => affine_from_rows(rows),
        }
    }

    /// This transform as a general matrix (rows of the 3x4 object-to-world matrix).
    #[must_use]
    pub fn to_rows(&self) -> MatrixRows {
        rows_from_affine(&self.world_from_object())
    }

    /// Every number in the transform, for finiteness checks.
    #[must_use]
    pub fn numbers(&self) -> Vec<f64> {
        match self {
            Transform::Trs(t) => [t.translate, t.rotate_deg, t.scale]
                .iter()
                .flat_map(|v| v.to_array())
                .collect(),
            Transform::Matrix(rows) => rows.iter().flatten().copied().collect(),
        }
    }
}

/// Builds an affine transform from the rows of a 3x4 matrix.
#[must_use]
pub fn affine_from_rows(rows: &MatrixRows) -> DAffine3 {
    let column = |c: usize| DVec3::new(rows[0][c], rows[1][c], rows[2][c]);
    DAffine3 {
        matrix3: DMat3::from_cols(column(0), column(1), column(2)),
        translation: column(3),
    }
}

/// The rows of the 3x4 matrix of an affine transform.
#[must_use]
pub fn rows_from_affine(affine: &DAffine3) -> MatrixRows {
    let m = affine.matrix3;
    let t = affine.translation;
    std::array::from_fn(|r| {
        let row = m.row(r);
        [row.x, row.y, row.z, t[r]]
    })
}

const TRS_FIELDS: &[&str] = &["translate", "rotate_deg", "scale"];

impl Serialize for Transform {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Transform::Trs(trs) => {
                let mut s = serializer.serialize_struct("Trs", 3)?;
                s.serialize_field("translate", &trs.translate)?;
                s.serialize_field("rotate_deg", &trs.rotate_deg)?;
                s.serialize_field("scale", &trs.scale)?;
                s.end()
            }
            Transform::Matrix(rows) => {
                let tuples: [(f64, f64, f64, f64); 3] = rows.map(|r| (r[0], r[1], r[2], r[3]));
                serializer.serialize_newtype_variant("Transform", 1, "Matrix", &tuples)
            }
        }
    }
}

impl<'de> Deserialize<'de> for Transform {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        deserializer.deserialize_any(TransformVisitor)
    }
}

struct TransformVisitor;

impl<'de> Visitor<'de> for TransformVisitor {
    type Value = Transform;

    fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(
            "a transform: (translate: .., rotate_deg: .., scale: ..) or Matrix(((..), (..), (..)))",
        )
    }

    /// `(translate: .., rotate_deg: .., scale: ..)`, each part optional.
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Transform, A::Error> {
        let mut trs = Trs::default();
        let mut seen = [false; 3];
        while let Some(key) = map.next_key::<String>()? {
            let index = TRS_FIELDS
                .iter()
                .position(|f| *f == key)
                .ok_or_else(|| de::Error::unknown_field(&key, TRS_FIELDS))?;
            if std::mem::replace(&mut seen[index], true) {
                return Err(de::Error::duplicate_field(TRS_FIELDS[index]));
            }
            let value: DVec3 = map.next_value()?;
            match index {
                0 => trs.translate = value,
                1 => trs.rotate_deg = value,
                _ => trs.scale = value,
            }
        }
        Ok(Transform::Trs(trs))
    }

    /// `Matrix(((..), (..), (..)))` arrives as a one-element sequence holding the rows;
    /// the rows written without the extra parentheses are accepted too.
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Transform, A::Error> {
        let first: MatrixElement = seq
            .next_element()?
            .ok_or_else(|| de::Error::invalid_length(0, &"three rows of four numbers"))?;
        let rows = match first {
            MatrixElement::Rows(rows) => rows,
            MatrixElement::Row(r0) => {
                let r1: [f64; 4] = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(1, &"three rows of four numbers"))?;
                let r2: [f64; 4] = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(2, &"three rows of four numbers"))?;
                [r0, r1, r2]
            }
        };
        if seq.next_element::<de::IgnoredAny>()?.is_some() {
            return Err(de::Error::custom(
                "a Matrix transform has exactly three rows of four numbers",
            ));
        }
        Ok(Transform::Matrix(rows))
    }
}

/// One element of a matrix sequence: either all three rows, or a single row.
enum MatrixElement {
    Rows(MatrixRows),
    Row([f64; 4]),
}

impl<'de> Deserialize<'de> for MatrixElement {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct ElementVisitor;
        impl<'de> Visitor<'de> for ElementVisitor {
            type Value = MatrixElement;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("three rows of four numbers")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<MatrixElement, A::Error> {
                // A row holds numbers; the rows tuple holds tuples. Peek by trying a row.
                let first: RowOrNumber = seq
                    .next_element()?
                    .ok_or_else(|| de::Error::invalid_length(0, &self))?;
                match first {
                    RowOrNumber::Number(x0) => {
                        let mut row = [x0, 0.0, 0.0, 0.0];
                        for (i, slot) in row.iter_mut().enumerate().skip(1) {
                            *slot = seq
                                .next_element()?
                                .ok_or_else(|| de::Error::invalid_length(i, &"four numbers"))?;
                        }
                        if seq.next_element::<de::IgnoredAny>()?.is_some() {
                            return Err(de::Error::custom("a matrix row has exactly four numbers"));
                        }
                        Ok(MatrixElement::Row(row))
                    }
                    RowOrNumber::Row(r0) => {
                        let r1: [f64; 4] = seq
                            .next_element()?
                            .ok_or_else(|| de::Error::invalid_length(1, &self))?;
                        let r2: [f64; 4] = seq
                            .next_element()?
                            .ok_or_else(|| de::Error::invalid_length(2, &self))?;
                        if seq.next_element::<de::IgnoredAny>()?.is_some() {
                            return Err(de::Error::custom(
                                "a Matrix transform has exactly three rows of four numbers",
                            ));
                        }
                        Ok(MatrixElement::Rows([r0, r1, r2]))
                    }
                }
            }
        }
        deserializer.deserialize_any(ElementVisitor)
    }
}

/// Either a number or a row of four numbers.
enum RowOrNumber {
    Number(f64),
    Row([f64; 4]),
}

impl<'de> Deserialize<'de> for RowOrNumber {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = RowOrNumber;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or a row of four numbers")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<RowOrNumber, E> {
                Ok(RowOrNumber::Number(v))
            }
            fn visit_f32<E: de::Error>(self, v: f32) -> Result<RowOrNumber, E> {
                Ok(RowOrNumber::Number(f64::from(v)))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<RowOrNumber, E> {
                Ok(RowOrNumber::Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<RowOrNumber, E> {
                Ok(RowOrNumber::Number(v as f64))
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<RowOrNumber, A::Error> {
                let mut row = [0.0; 4];
                for (i, slot) in row.iter_mut().enumerate() {
                    *slot = seq
                        .next_element()?
                        .ok_or_else(|| de::Error::invalid_length(i, &"four numbers"))?;
                }
                if seq.next_element::<de::IgnoredAny>()?.is_some() {
                    return Err(de::Error::custom("a matrix row has exactly four numbers"));
                }
                Ok(RowOrNumber::Row(row))
            }
        }
        deserializer.deserialize_any(V)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_trs_gives_back_a_shear_free_placement() {
        let trs = Trs {
            translate: DVec3::new(1.0, -2.0, 0.5),
            rotate_deg: DVec3::new(20.0, -35.0, 70.0),
            scale: DVec3::new(2.0, 0.5, 1.5),
        };
        let back = Trs::nearest(&trs.world_from_object());
        let a = trs.world_from_object();
        let b = back.world_from_object();
        assert!(a.abs_diff_eq(b, 1e-9), "{a:?} vs {b:?}");
        assert!(matches!(
            Transform::from_affine(&a),
            Transform::Trs(t) if t.world_from_object().abs_diff_eq(a, 1e-9)
        ));
    }

    #[test]
    fn a_sheared_placement_stays_a_matrix() {
        let shear = DAffine3 {
            matrix3: DMat3::from_cols(DVec3::X, DVec3::new(0.5, 1.0, 0.0), DVec3::Z),
            translation: DVec3::new(3.0, 0.0, -1.0),
        };
        assert_eq!(
            Transform::from_affine(&shear),
            Transform::Matrix(rows_from_affine(&shear))
        );
    }

    #[test]
    fn trs_applies_scale_then_x_y_z_rotation_then_translation() {
        let trs = Trs {
            translate: DVec3::new(1.0, 2.0, 3.0),
            rotate_deg: DVec3::new(90.0, 90.0, 0.0),
            scale: DVec3::new(2.0, 1.0, 1.0),
        };
        // x axis: scaled to 2, Rx leaves it, Ry(90) takes +x to -z.
        let p = trs.world_from_object().transform_point3(DVec3::X);
        assert!((p - DVec3::new(1.0, 2.0, 1.0)).length() < 1e-12, "{p}");
        // y axis: Rx(90) takes +y to +z, Ry(90) takes +z to +x.
        let q = trs.world_from_object().transform_vector3(DVec3::Y);
        assert!((q - DVec3::X).length() < 1e-12, "{q}");
    }

    #[test]
    fn quarter_turns_are_exact_and_agree_with_glam() {
        for degrees in [-270.0, -90.0, 0.0, 90.0, 180.0, 450.0, -720.0, 9e20] {
            let (s, c) = sin_cos_deg(degrees);
            let r = f64::to_radians(degrees % 360.0);
            assert!((s - r.sin()).abs() < 1e-15 && (c - r.cos()).abs() < 1e-15);
            assert!(s.fract() == 0.0 && c.fract() == 0.0);
        }
        let trs = Trs {
            rotate_deg: DVec3::new(31.0, -47.0, 112.0),
            ..Trs::default()
        };
        let r = trs.rotate_deg * (std::f64::consts::PI / 180.0);
        let glam_rotation =
            DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
        assert!(
            trs.world_from_object()
                .matrix3
                .abs_diff_eq(glam_rotation, 1e-15)
        );
        let floor = Trs {
            rotate_deg: DVec3::new(-90.0, 0.0, 0.0),
            ..Trs::default()
        };
        assert_eq!(
            floor.world_from_object().transform_vector3(DVec3::Z),
            DVec3::Y
        );
    }

    #[test]
    fn tiny_and_large_angles_keep_their_precision() {
        // A tiny negative angle is nearly no turn (not 270 degrees).
        let (s, c) = sin_cos_deg(-1e-15);
        assert!(s < 0.0 && s > -1e-16 && c == 1.0, "({s}, {c})");
        // 3600.5 degrees is exactly 0.5 degrees after reduction.
        assert_eq!(sin_cos_deg(3600.5), sin_cos_deg(0.5));
        assert_eq!(sin_cos_deg(-30.0), (-30f64).to_radians().sin_cos());
        assert!(sin_cos_deg(f64::NAN).0.is_nan() && sin_cos_deg(f64::INFINITY).1.is_nan());
    }

    #[test]
    fn rows_round_trip() {
        let trs = Trs {
            translate: DVec3::new(1.0, -2.0, 3.0),
            rotate_deg: DVec3::new(10.0, 20.0, 30.0),
            scale: DVec3::new(2.0, 0.5, 1.5),
        };
        let a = trs.world_from_object();
        let b = affine_from_rows(&rows_from_affine(&a));
        assert_eq!(a, b);
    }
}
