//! A CSG node compiled for the tracer: its operand leaves placed in the node's own
//! object space, and its operators as a post-order program (`tree`), built from the
//! scene with a work list (`build`). A ray is answered by running the program (`eval`),
//! which sweeps the leaves' spans together (`spans`) with explicit stacks, so a tree
//! 1,000 levels deep needs no deeper call stack than a flat one.

mod build;
mod eval;
mod spans;
mod tree;
#[cfg(test)]
mod tree_tests;

pub use tree::{CsgHit, CsgLeaf, CsgTree, Extent};
