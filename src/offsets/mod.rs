//! The offset rules proper: how G43/G44/G49 (seed 001), G45–G48 (seeds 000,
//! 003) and lathe T codes (seed 004) turn register values into vectors and
//! changed movement amounts. The machine owns positions and modal state and
//! calls these; nothing here moves the tool or formats text.

pub mod lathe;
pub mod length;
pub mod position;
