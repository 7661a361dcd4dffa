//! The toolpath of a run built as its moves are made, and of a run made
//! again after an edit from the earlier run's toolpath.

use super::Toolpath;
use crate::machine::Move;
use crate::report::Run;
use crate::setup::{MachineKind, Units};

/// Builds the toolpath of a run as its moves are made (an
/// [`crate::run::Observer`]); for a run made again after an edit
/// ([`crate::rerun_observed`]), from the earlier run's toolpath before and
/// after the moves made again.
pub struct PathBuilder<'a> {
    path: Toolpath,
    earlier: Option<&'a Toolpath>,
    /// Whether [`PathBuilder::foresee`] has made room.
    foreseen: bool,
}

impl<'a> PathBuilder<'a> {
    /// A builder for a run of a `machine` set up in `units`; `earlier` is
    /// the toolpath of the earlier run when the run is made again.
    pub fn new(machine: MachineKind, units: Units, earlier: Option<&'a Toolpath>) -> Self {
        PathBuilder {
            path: Toolpath::new(machine, units),
            earlier,
            foreseen: false,
        }
    }

    /// `read` of the program's `total` bytes have been run: room, at once,
    /// for the moves of the rest at the rate so far (once, on the first
    /// call). Growing the arrays by doubling copied each of them about
    /// once more and touched twice the memory; in wasm, where every page
    /// touched for the first time is a fault, that was a fifth of the first
    /// run of a 1M-block program (V8 profile, `docs/performance.md`).
    pub fn foresee(&mut self, read: usize, total: usize) {
        if self.foreseen || read == 0 || total <= read {
            return;
        }
        self.foreseen = true;
        let scale = total as f64 / read as f64 * 1.05;
        let lengths = self.path.lengths().map(|len| (len as f64 * scale) as usize);
        self.path.reserve_to(lengths);
    }

    /// The toolpath of `run`, which `reuse` says what it took from the
    /// earlier run.
    pub fn finish(mut self, run: &Run, reuse: &crate::run::again::Reuse) -> Toolpath {
        if let (Some(earlier), Some(tail)) = (self.earlier, reuse.tail) {
            self.path.append_moves(
                earlier,
                tail.from_move..earlier.len(),
                tail.blocks,
                tail.lines,
            );
        }
        if self.path.is_empty() {
            // No move to take the units from: the run's (G20/G21 may still
            // have been read).
            self.path = Toolpath::new(run.machine, run.units);
        } else {
            // The moves were added without growing the bounds: the run grew
            // its own with the same points (and those of the moves taken
            // from the earlier run).
            self.path.set_bounds(run.bounds);
        }
        self.path
    }
}

impl crate::run::Observer for PathBuilder<'_> {
    fn on_move(&mut self, m: &Move) {
        self.path.push_move(m, false);
    }

    fn on_resume(&mut self, prefix_moves: usize) {
        if let Some(earlier) = self.earlier {
            // An edit's path is about as long as the earlier one: room for
            // it at once, instead of growing (copying) the arrays.
            self.foreseen = true;
            self.path.reserve_to(earlier.lengths());
            self.path.append_moves(earlier, 0..prefix_moves, 0, 0);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Setup, run};

    #[test]
    fn a_path_built_as_it_runs_takes_the_run_s_bounds_which_are_those_of_its_moves() {
        // The builder adds moves without growing the bounds and takes the
        // run's (in mm) at the end, in the path's units: the box that
        // growing them move by move gives — arcs' extremes, inches, the
        // lathe's diameters, offsets moving the actual path.
        let lathe = Setup {
            machine: MachineKind::Lathe,
            ..Setup::default()
        };
        let mut offsets = Setup::default();
        offsets.set_register("01=6.0").unwrap();
        let cases = [
            (
                "G20 G90 G00 X1. Y1.\nG01 X2.5 F10.\nG02 X2.5 Y1. I-.75\nG03 X1. Y2. R1.2\n",
                Setup::default(),
            ),
            (
                "G90 G00 X0 Y0\nG91 G46 X30. Y20. D01\nG01 G47 X80. F200.\nG02 X10. Y10. R10.\n",
                offsets,
            ),
            (
                "G18 G00 X40. Z5.\nG01 Z-10. F0.2\nG02 X60. Z-20. R10.\n",
                lathe,
            ),
        ];
        for (program, setup) in cases {
            let r = run(program, &setup);
            assert!(!r.has_errors(), "{:?}", r.diagnostics);
            let mut b = PathBuilder::new(r.machine, r.units, None);
            for m in &r.moves {
                crate::run::Observer::on_move(&mut b, m);
            }
            let built = b.finish(&r, &crate::Reuse::default());
            assert!(built.bounds.is_some(), "{program}");
            assert_eq!(built, Toolpath::from_run(&r), "{program}");
        }
    }

    #[test]
    fn room_foreseen_after_part_of_a_run_holds_the_rest_and_changes_nothing() {
        let r = run(
            &"G01 X1. Y2. F100.\nG02 X3. Y4. R5.\n".repeat(2000),
            &Setup::default(),
        );
        let plain = Toolpath::from_run(&r);
        let mut b = PathBuilder::new(r.machine, r.units, None);
        for (i, m) in r.moves.iter().enumerate() {
            if i == r.moves.len() / 4 {
                // A quarter of the moves from a quarter of the text.
                b.foresee(1, 4);
                let room = b.path.kinds.capacity();
                assert!(room >= r.moves.len(), "{room} for {} moves", r.moves.len());
                b.foresee(1, 8); // once only
                assert_eq!(b.path.kinds.capacity(), room);
            }
            crate::run::Observer::on_move(&mut b, m);
        }
        let room = (b.path.actual.capacity(), b.path.arcs.capacity());
        let built = b.finish(&r, &crate::Reuse::default());
        assert_eq!(built, plain);
        assert_eq!(
            (built.actual.capacity(), built.arcs.capacity()),
            room,
            "no copy grew them"
        );
        // Nothing read, or all of it: nothing to foresee.
        let mut b = PathBuilder::new(r.machine, r.units, None);
        b.foresee(0, 10);
        b.foresee(10, 10);
        assert_eq!(b.path.kinds.capacity(), 0);
    }
}
