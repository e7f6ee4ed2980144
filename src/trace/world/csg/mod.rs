//! A CSG node compiled for the tracer: its operand leaves placed in the node's own
//! object space, and its operators as a post-order program (`tree`), built from the
//! scene with a work list (`build`). A ray runs the program (`eval`), which sweeps the
//! leaves' spans together (`spans`) with explicit stacks, so a tree 1,000 levels deep
//! needs no deeper call stack than a flat one; `query` answers from the spans. An
//! Intersection of convex primitives skips the program (`convex`).

mod build;
mod convex;
mod eval;
mod query;
mod spans;
mod tree;
#[cfg(test)]
mod tree_tests;

pub use tree::{CsgHit, CsgLeaf, CsgTree, Extent};
