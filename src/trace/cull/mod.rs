//! What a tile's rays can meet: the objects in a tile's view and in its shadow rays' way,
//! found once per tile so that most rays test a few objects instead of all.

mod shadows;
mod tiles;

pub use tiles::{Candidates, TileCull};
