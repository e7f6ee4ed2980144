//! OBJ text built in code for the mesh tests: a flat sheet of `n` x `n` quads, large
//! enough at a few hundred a side that its reading can be watched and cancelled.

use std::fmt::Write;

/// A sheet of `n` x `n` quads in z = 0 (`(n + 1)^2` vertices), each quad one `f` line
/// of four corners, or two triangles where `triangles` is set.
#[must_use]
pub fn sheet(n: usize, triangles: bool) -> String {
    let mut text = String::with_capacity(n * n * 60);
    for j in 0..=n {
        for i in 0..=n {
            writeln!(text, "v {i} {j} 0").unwrap();
        }
    }
    let v = |i: usize, j: usize| j * (n + 1) + i + 1;
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1));
            if triangles {
                writeln!(text, "f {a} {b} {c}\nf {a} {c} {d}").unwrap();
            } else {
                writeln!(text, "f {a} {b} {c} {d}").unwrap();
            }
        }
    }
    text
}
