//! The offset families, one file each with all of its rules, its
//! explanation sentences and its tests: how register values become vectors
//! and changed movement amounts, what a block holding the offset may hold,
//! and what the report says it did.
//!
//! - [`length`]: tool length offset G43/G44/G49 (behaviour 3, seed 001);
//! - [`position`]: tool position offset G45–G48 (behaviour 4, seeds 000, 003);
//! - [`lathe`]: lathe T-code tool position offset (behaviour 5, seed 004);
//! - [`cutter`]: cutter radius compensation C, G40–G42 and G39 (behaviour 16),
//!   a folder with its plane geometry.
//!
//! The machine owns positions and modal state and calls these; a family
//! never moves the tool and imports nothing of the machine.

pub mod cutter;
pub mod lathe;
pub mod length;
pub mod position;
