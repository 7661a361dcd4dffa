//! The settings where controls disagree (behaviour 7) and the control
//! profile that gives their defaults (behaviour 12): each such setting is an
//! `Option` read through its accessor, which holds the one `match` on the
//! control.

use serde::{Deserialize, Serialize};

use super::choices::*;
use super::is_default;

/// Settings where controls disagree; the seeds' behaviour is the default.
/// A setting whose default depends on the control is an `Option` read
/// through its accessor (`None`: the control's default).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Settings {
    /// The control profile (behaviour 12): the defaults of the settings below
    /// that are left out.
    #[serde(skip_serializing_if = "is_default")]
    pub control: Control,
    /// Dimension words without a decimal point (behaviour 1.15); read it
    /// with [`Settings::decimal_input`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub decimal_input: Option<DecimalInput>,
    /// Optional block skip switch: when on, blocks starting with `/` are skipped.
    #[serde(skip_serializing_if = "is_default")]
    pub block_skip: bool,
    /// Skip a block that cannot run and go on (behaviour 2.24, 7.48).
    #[serde(skip_serializing_if = "is_default")]
    pub continue_past_errors: bool,
    /// `start`, `reference` left out (7.49, 13.15): `machine_positions()`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub machine_positions: Option<super::MachinePositions>,
    /// `G43 H…` with no Z word (behaviour 3.3); read it with
    /// [`Settings::length_offset_without_z`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_offset_without_z: Option<LengthOffsetWithoutZ>,
    /// Lathe table X values: diameter or radius (behaviour 5).
    #[serde(skip_serializing_if = "is_default")]
    pub lathe_x_offset: LatheXOffset,
    /// Mirror image switches (mill).
    #[serde(skip_serializing_if = "is_default")]
    pub mirror: Mirror,
    /// Retract amount `d` of the G73/G83 peck cycles, in setup units
    /// (a machine parameter on a real control). Default 1 mm / 0.04 in.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub peck_retract: Option<f64>,
    /// The rapid traverse rate of every axis, in setup units per minute,
    /// for the cycle time estimate (behaviour 6.10, 7.41; a machine
    /// parameter on a real control, Fanuc 1420). Default 24,000 mm/min.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rapid_rate: Option<f64>,
    /// Two G codes of one modal group in a block (behaviour 7.17); read it
    /// with [`Settings::same_group_codes`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub same_group_codes: Option<SameGroupCodes>,
    /// The lathe's G-code system (behaviour 7.18); read it with
    /// [`Settings::gcode_system`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub gcode_system: Option<GCodeSystem>,
    /// A decimal point in a dwell's P (behaviour 7.26); read it with
    /// [`Settings::dwell_p_decimal_point`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dwell_p_decimal_point: Option<DwellPDecimalPoint>,
    /// A decimal point in S (behaviour 7.57); read it with
    /// [`Settings::s_decimal_point`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub s_decimal_point: Option<SDecimalPoint>,
    /// The macro words' abbreviations (behaviour 7.59); read it with
    /// [`Settings::macro_abbreviations`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub macro_abbreviations: Option<MacroAbbreviations>,
    /// Roughing words on a G70 block (behaviour 7.58); read it with
    /// [`Settings::finishing_extra_words`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub finishing_extra_words: Option<FinishingExtraWords>,
    /// What `;` is (behaviour 7.61); read it with [`Settings::semicolon`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub semicolon: Option<Semicolon>,
    /// G47 on the mill (behaviour 7.60); read it with [`Settings::g47`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub g47: Option<G47Code>,
    /// G12/G13 on the mill (behaviour 7.20); read it with
    /// [`Settings::circle_pocket`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub circle_pocket: Option<CirclePocket>,
    /// G28/G30 without an axis word (behaviour 7.21); read it with
    /// [`Settings::reference_return_without_axes`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reference_return_without_axes: Option<ReturnWithoutAxes>,
    /// G54.1 Pn or G154 Pn (behaviour 7.22); read it with
    /// [`Settings::extended_work_offsets`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub extended_work_offsets: Option<ExtendedWork>,
    /// G68's R in G91 (behaviour 7.23).
    #[serde(skip_serializing_if = "is_default")]
    pub rotation_angle: RotationAngle,
    /// How D reads in a lathe G71/G72/G74–G76 block (behaviour 7.24, 15.2);
    /// read it with [`Settings::depth_word`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub depth_word: Option<DepthWord>,
    /// What the G00 blocks that end a G71/G72 contour going back toward
    /// the start are (behaviour 7.25, 15.6); read it with
    /// [`Settings::trailing_rapids`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trailing_rapids: Option<TrailingRapids>,
    /// Where a G70–G73 contour may write G40/G41/G42 (behaviour 7.34,
    /// 18.11); read it with [`Settings::nose_in_contour`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nose_in_contour: Option<NoseInContour>,
    /// Tool nose radius compensation in G90/G94 (behaviour 7.35, 18.15);
    /// read it with [`Settings::nose_single_cycles`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub nose_single_cycles: Option<NoseSingleCycles>,
    /// Cutter compensation start-up and cancel type (behaviour 16.3); read
    /// it with [`Settings::cutter_start_up`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_start_up: Option<CutterStartUp>,
    /// Outside corners in offset mode (behaviour 16.7); read it with
    /// [`Settings::cutter_outside_corner`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_outside_corner: Option<CutterOutsideCorner>,
    /// G40/D00 without a move in the plane (behaviour 16.11); read it with
    /// [`Settings::cutter_cancel_without_motion`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_cancel_without_motion: Option<CutterCancelWithoutMotion>,
    /// How many blocks without a move in the plane the control reads past
    /// to find the next move in offset mode (behaviour 16.9); read it with
    /// [`Settings::cutter_blocks_without_motion`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cutter_blocks_without_motion: Option<u8>,
    /// The interference check (behaviour 16.12).
    #[serde(skip_serializing_if = "is_default")]
    pub cutter_interference_check: CutterInterference,
    /// The mill's offset memory type (behaviour 7.32, 17.1); read it with
    /// [`Settings::offset_memory`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub offset_memory: Option<OffsetMemory>,
    /// How a program writes the face plane in polar coordinate
    /// interpolation (behaviour 7.33, 14.11); read it with
    /// [`Settings::polar_interpolation`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub polar_interpolation: Option<PolarInterpolation>,
    /// The range of ATAN and ASIN (behaviour 7.39); read it with
    /// [`Settings::macro_angles`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub macro_angles: Option<MacroAngles>,
    /// What a macro condition is (behaviour 7.40); read it with
    /// [`Settings::macro_conditions`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub macro_conditions: Option<MacroConditions>,
    /// How M98's P reads (behaviour 7.36, 19.3); read it with
    /// [`Settings::subprogram_p`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subprogram_p: Option<SubprogramP>,
    /// How many subprogram calls may be open at once (behaviour 7.37,
    /// 19.6); read it with [`Settings::subprogram_nesting`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub subprogram_nesting: Option<u8>,
    /// What M99 in the main program does (behaviour 7.42, 19.4); read it
    /// with [`Settings::main_m99`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub main_m99: Option<MainM99>,
    /// How many macro calls (G65, G66) may be open at once (behaviour
    /// 7.45, 21.4); read it with [`Settings::macro_nesting`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub macro_nesting: Option<u8>,
    /// The arc radius check's tolerance in setup units (behaviour 7.56,
    /// 2.13): Fanuc parameter 3410; read it with
    /// [`crate::setup::Setup::arc_tolerance_mm`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub arc_tolerance: Option<f64>,
}

impl Settings {
    /// `G43 H…` with no Z word (behaviour 3.3): Z moves by the offset in
    /// that block on YASNAC (seed 001), and so the Fanuc and Haas profiles;
    /// LinuxCNC moves nothing and the next Z move carries the offset
    /// (`rs274 -g`: no motion at a G43 without Z, behaviour 22.3).
    pub fn length_offset_without_z(&self) -> LengthOffsetWithoutZ {
        self.length_offset_without_z.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => LengthOffsetWithoutZ::Move,
            Control::Linuxcnc => LengthOffsetWithoutZ::NextZ,
        })
    }

    /// Dimension words without a decimal point (behaviour 1.15): the
    /// least input increment on the Fanuc family (`X1` is 0.001 mm);
    /// LinuxCNC reads every number as a value in units (RS274/NGC
    /// language, "Numbers": `X1` is 1 mm).
    pub fn decimal_input(&self) -> DecimalInput {
        self.decimal_input.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => DecimalInput::Increment,
            Control::Linuxcnc => DecimalInput::Calculator,
        })
    }

    /// Two G codes of one group in a block: YASNAC refuses the block (an
    /// input error, as it refuses two of G45–G48, seed 003); Fanuc documents
    /// that the last one specified is valid (0i-MF/TF operator's manuals,
    /// "Preparatory function (G function)"), and the Haas profile follows
    /// the Fanuc rule its manuals are written against.
    pub fn same_group_codes(&self) -> SameGroupCodes {
        self.same_group_codes.unwrap_or(match self.control {
            // LinuxCNC: "two G-codes from the same modal group" is an error
            // (RS274/NGC language, "Modal groups").
            Control::Yasnac | Control::Linuxcnc => SameGroupCodes::Error,
            Control::Fanuc | Control::Haas => SameGroupCodes::LastWins,
        })
    }

    /// What `;` is (behaviour 7.61): the end of a block in ISO code, as
    /// the Fanuc, Haas and YASNAC manuals write EOB; a comment to the end
    /// of the line on LinuxCNC (RS274/NGC language, "Comments").
    pub fn semicolon(&self) -> Semicolon {
        self.semicolon.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => Semicolon::EndOfBlock,
            Control::Linuxcnc => Semicolon::Comment,
        })
    }

    /// What G47 is on the mill (behaviour 7.60): Haas engraves text with
    /// it (Haas mill operator's manual, "G47 Text Engraving"); Fanuc and
    /// YASNAC offset the tool position (seeds 000 and 003).
    pub fn g47(&self) -> G47Code {
        self.g47.unwrap_or(match self.control {
            Control::Haas => G47Code::Engraving,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => G47Code::PositionOffset,
        })
    }

    /// G12/G13 on the mill: Haas mills cut a circular pocket (Haas mill
    /// operator's manual, "G12 Circular Pocket Milling CW / G13 … CCW");
    /// neither the Fanuc 0i-MF G-code list nor the YASNAC seeds' manual has
    /// them on the mill, where the control alarms.
    pub fn circle_pocket(&self) -> CirclePocket {
        self.circle_pocket.unwrap_or(match self.control {
            Control::Haas => CirclePocket::Haas,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => CirclePocket::Alarm,
        })
    }

    /// The lathe's G-code system: A on every profile (Fanuc's default, the
    /// parameters GSB/GSC of No. 3401 choosing B or C; Haas lathes and the
    /// seed 004 manual write system A).
    pub fn gcode_system(&self) -> GCodeSystem {
        self.gcode_system.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas | Control::Linuxcnc => GCodeSystem::A,
        })
    }

    /// G71's words on a G70 block (behaviour 7.58): Fanuc alarms (PS0066),
    /// Haas programs copy them there and run.
    pub fn finishing_extra_words(&self) -> FinishingExtraWords {
        self.finishing_extra_words.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => FinishingExtraWords::Error,
            Control::Haas => FinishingExtraWords::Warn,
        })
    }

    /// Fanuc programs abbreviate the macro words (`WH[…]DO1`); Haas's and
    /// YASNAC's macro chapters write them in full (behaviour 7.59).
    pub fn macro_abbreviations(&self) -> MacroAbbreviations {
        self.macro_abbreviations.unwrap_or(match self.control {
            Control::Fanuc => MacroAbbreviations::Fanuc,
            Control::Yasnac | Control::Haas | Control::Linuxcnc => MacroAbbreviations::Off,
        })
    }

    /// A decimal point in S: Fanuc allows none (PS0007 ILLEGAL USE OF
    /// DECIMAL POINT, an address that takes no point), nor do the YASNAC
    /// tables, which give S as an integer; Haas programs write `S5000.`
    /// and run (behaviour 7.57 says what is and is not known).
    pub fn s_decimal_point(&self) -> SDecimalPoint {
        self.s_decimal_point.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc => SDecimalPoint::Error,
            // LinuxCNC: every word's value is a real number.
            Control::Haas | Control::Linuxcnc => SDecimalPoint::Value,
        })
    }

    /// A decimal point in a dwell's P: Fanuc allows none in P (0i-MF/TF
    /// operator's manuals, "Dwell (G04)": X takes a decimal point, P does
    /// not; alarm PS0007, illegal use of decimal point), nor does YASNAC,
    /// whose P is a whole number of milliseconds; Haas reads P with a point
    /// as seconds and without one as milliseconds (mill and lathe operator's
    /// manuals, G04), and its canned cycles' P the same way.
    pub fn dwell_p_decimal_point(&self) -> DwellPDecimalPoint {
        self.dwell_p_decimal_point.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc => DwellPDecimalPoint::Error,
            Control::Haas => DwellPDecimalPoint::Seconds,
            Control::Linuxcnc => DwellPDecimalPoint::Always,
        })
    }

    /// G28/G30 without an axis word: Haas returns every axis (mill and lathe
    /// operator's manuals, G28); Fanuc returns the axes the block names, so
    /// none (0i-MF/TF operator's manuals, "Reference position return": the
    /// axes commanded return); the YASNAC manuals at hand do not say, and the
    /// profile follows the Fanuc family (our convention).
    pub fn reference_return_without_axes(&self) -> ReturnWithoutAxes {
        self.reference_return_without_axes
            .unwrap_or(match self.control {
                // LinuxCNC: G28 alone goes to the G28 position (#5161…).
                Control::Haas | Control::Linuxcnc => ReturnWithoutAxes::AllAxes,
                Control::Yasnac | Control::Fanuc => ReturnWithoutAxes::NoAxis,
            })
    }

    /// The additional work systems: Haas writes G154 P1–P99 (mill operator's
    /// manual, G154); Fanuc G54.1 P1–P48 or G54 P1–P48 (0i-MF operator's
    /// manual, "Adding workpiece coordinate systems"); YASNAC follows Fanuc
    /// (our convention).
    pub fn extended_work_offsets(&self) -> ExtendedWork {
        self.extended_work_offsets.unwrap_or(match self.control {
            Control::Haas => ExtendedWork::G154,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => ExtendedWork::G54_1,
        })
    }

    /// The range of ATAN and ASIN: Fanuc's parameter NAT (No. 6004#0) is 0
    /// as shipped, ATAN 0 to 360 and ASIN 270 to 90 (0i-MF/TF operator's
    /// manuals, "Arithmetic and logic operation"); the YASNAC and Haas
    /// manuals at hand do not say, and follow (our convention).
    pub fn macro_angles(&self) -> MacroAngles {
        self.macro_angles.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => MacroAngles::Positive,
            // LinuxCNC: ATAN[y]/[x] in −180…180, ASIN −90…90 (`rs274 -g`).
            Control::Linuxcnc => MacroAngles::Signed,
        })
    }

    /// What a macro condition is: Fanuc's comparisons are true or false and
    /// cannot be stored (0i-MF/TF operator's manuals, "Arithmetic and logic
    /// operation"; alarm PS0114); Haas: every expression is a number, a
    /// condition 0.0 false and any other true (Haas mill operator's manual
    /// 96-8000, "Macros", Conditional expressions). YASNAC follows Fanuc.
    pub fn macro_conditions(&self) -> MacroConditions {
        self.macro_conditions.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc => MacroConditions::Boolean,
            // LinuxCNC: a condition is true when not 0 (O-codes, "if").
            Control::Haas | Control::Linuxcnc => MacroConditions::Numeric,
        })
    }

    /// How M98's P reads (behaviour 7.36): Fanuc and YASNAC write the
    /// repeat count before a four-digit program number in one P
    /// (`M98 P50010`: O0010 five times; Fanuc 0i-MF/TF operator's manuals,
    /// "Subprogram call"); Haas numbers programs with five digits and
    /// repeats only with L (Haas mill operator's manual, M98).
    pub fn subprogram_p(&self) -> SubprogramP {
        self.subprogram_p.unwrap_or(match self.control {
            Control::Haas => SubprogramP::Number,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => SubprogramP::RepeatAndNumber,
        })
    }

    /// What M99 in the main program does (behaviour 7.42): every control
    /// goes back to the program's start and runs it again until the
    /// operator stops it (Fanuc 0i-MF/TF, "Subprogram call": M99 in a main
    /// program; Haas mill operator's manual, M99 "loop"); a viewer draws
    /// one pass unless asked for the loop, the same on every profile.
    pub fn main_m99(&self) -> MainM99 {
        self.main_m99.unwrap_or(MainM99::Once)
    }

    /// How many subprogram calls may be open at once (behaviour 7.37):
    /// Fanuc 0i-F and 30i nest subprogram calls 10 deep (the operator's
    /// manuals, "Subprogram call"; earlier Fanuc controls 4), past which
    /// alarm PS0077 stops the program; YASNAC 4 and Haas 4 (our convention:
    /// the manuals at hand give no figure), at least 1.
    pub fn subprogram_nesting(&self) -> u32 {
        match self.subprogram_nesting {
            Some(n) => u32::from(n.max(1)),
            None => match self.control {
                Control::Fanuc => 10,
                Control::Yasnac | Control::Haas | Control::Linuxcnc => 4,
            },
        }
    }

    /// How many macro calls may be open at once (behaviour 7.45): Fanuc 4
    /// (16i/18i operator's manual, 16 "Custom macro", "Call nesting": four
    /// levels of G65 and G66 calls, subprogram calls not counted), and so
    /// the YASNAC and Haas profiles (our convention), at least 1.
    pub fn macro_nesting(&self) -> u32 {
        self.macro_nesting.map_or(4, |n| u32::from(n.max(1)))
    }

    /// How the D word of the one-block G71/G72 (depth of cut), G74/G75
    /// (relief) and G76 (first depth) reads (behaviour 7.24): Haas reads it
    /// as a length with a decimal point (Haas lathe operator's manual, G71:
    /// "D – depth of cut for each pass, positive radius", written `D0.05`);
    /// the Fanuc Series 10/11 tape format of the 0i-TF (parameter FCV) in
    /// least input increments, without a decimal point (`D7000` = 7 mm).
    /// YASNAC (the seeds' control) writes it as Haas's YASNAC mode does:
    /// a length.
    pub fn trailing_rapids(&self) -> TrailingRapids {
        // Fanuc checks every block from P to Q (a shape that turns back is
        // PS0064/PS0329); Haas school programs end the contour with `G00
        // G40 Z0.1` back to the start and run: our reading of the Haas
        // profile takes those rapids as the exit.
        self.trailing_rapids.unwrap_or(match self.control {
            Control::Haas => TrailingRapids::Exit,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => TrailingRapids::Shape,
        })
    }

    /// Where a G70–G73 contour may write G40/G41/G42: in the contour on
    /// Haas (its school programs start the compensation in the P block and
    /// end it in the Q block) and YASNAC (our convention); only before the
    /// cycle on Fanuc (our reading of the 0i-F / 30i-B manuals' restriction
    /// on the shape program, alarm PS0325).
    pub fn nose_in_contour(&self) -> NoseInContour {
        self.nose_in_contour.unwrap_or(match self.control {
            Control::Haas | Control::Yasnac => NoseInContour::Contour,
            Control::Fanuc | Control::Linuxcnc => NoseInContour::BeforeCycle,
        })
    }

    /// G90/G94 with G41/G42 the mode: compensated on the side the tip
    /// direction gives on every profile (Fanuc 0i-TF, our reading of "tool
    /// nose radius compensation in canned cycles"; Haas and YASNAC our
    /// convention); `off` runs them as programmed with a warning.
    pub fn nose_single_cycles(&self) -> NoseSingleCycles {
        self.nose_single_cycles.unwrap_or(match self.control {
            Control::Haas | Control::Yasnac | Control::Fanuc | Control::Linuxcnc => {
                NoseSingleCycles::Tip
            }
        })
    }

    /// Cutter compensation start-up and cancel: type A on every profile —
    /// Fanuc's parameter SUP (No. 5003#0) is 0 as shipped, Haas's setting
    /// 43 is A by default; no YASNAC manual the project has describes a
    /// type B (our convention).
    pub fn cutter_start_up(&self) -> CutterStartUp {
        self.cutter_start_up.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => CutterStartUp::A,
            // rs274 -g: the entry move ends offset perpendicular to itself,
            // an outside corner to the next block is an arc (behaviour 22.9).
            Control::Linuxcnc => CutterStartUp::Corner,
        })
    }

    /// Outside corners: Fanuc's intersection and extra vectors (0i-MF,
    /// "Details of cutter compensation C", offset mode) on every profile;
    /// Haas's setting 58 is FANUC by default. The Haas manual says
    /// YASNAC-class controls go round outside corners otherwise (setting 58
    /// = YASNAC): `arc` is offsetlab's reading of that, unconfirmed by a
    /// YASNAC manual, so the YASNAC profile keeps the Fanuc rule (our
    /// convention).
    pub fn cutter_outside_corner(&self) -> CutterOutsideCorner {
        self.cutter_outside_corner.unwrap_or(match self.control {
            Control::Yasnac | Control::Fanuc | Control::Haas => CutterOutsideCorner::Vectors,
            // LinuxCNC goes round an outside corner on an arc of the tool
            // radius (RS274/NGC language, "Cutter compensation").
            Control::Linuxcnc => CutterOutsideCorner::Arc,
        })
    }

    /// G40 without a move in the plane: Fanuc takes the vector off in that
    /// block; Haas makes no change until the next X or Y move (Haas mill
    /// operator's manual, "Entry and exit from cutter compensation"); the
    /// YASNAC profile follows Fanuc (our convention).
    pub fn cutter_cancel_without_motion(&self) -> CutterCancelWithoutMotion {
        self.cutter_cancel_without_motion
            .unwrap_or(match self.control {
                Control::Yasnac | Control::Fanuc => CutterCancelWithoutMotion::Move,
                // rs274 -g: a G40 line without motion moves nothing; the
                // next move leaves the offset path (behaviour 22.9).
                Control::Haas | Control::Linuxcnc => CutterCancelWithoutMotion::NextMove,
            })
    }

    /// Blocks without a move in the plane read past in offset mode: 2 on
    /// every profile. Fanuc reads a parameter's number of blocks N (No.
    /// 19625 on the 0i-F, No. 6009 on the 15i) and finds the intersection
    /// while no more than N − 2 of them make no move (15i-MA operator's
    /// manual, 14.4.3); 2 is our reading of the common setting, and our
    /// convention for YASNAC and Haas.
    pub fn cutter_blocks_without_motion(&self) -> u8 {
        self.cutter_blocks_without_motion
            .unwrap_or(match self.control {
                Control::Yasnac | Control::Fanuc | Control::Haas | Control::Linuxcnc => 2,
            })
    }

    /// The mill's offset memory: YASNAC keeps one value per number, read by
    /// H and D alike (seed 001, table 3.4.1.2: one setting range of "offset
    /// values"; seed 003: "the offset value" changed by MDI), Fanuc's memory
    /// A; Haas keeps separate length (H) and diameter (D) columns, each
    /// geometry and wear (Haas mill operator's manual, "Tool offsets"; G10
    /// L10–L13), Fanuc's memory C. Fanuc's memory type is an option of the
    /// control (0i-MF/0i-B connection manuals, "Tool compensation memory");
    /// the profile takes memory C, the one Fanuc machining centres show as
    /// H and D geometry and wear columns and CAM posts write with G10
    /// L10–L13 (our reading: the standard option set is not in the manuals
    /// at hand).
    pub fn offset_memory(&self) -> OffsetMemory {
        self.offset_memory.unwrap_or(match self.control {
            Control::Yasnac => OffsetMemory::A,
            Control::Fanuc | Control::Haas | Control::Linuxcnc => OffsetMemory::C,
        })
    }

    /// The words of polar coordinate interpolation on the lathe (behaviour
    /// 7.33): the Fanuc T manuals write the face in X, a diameter as
    /// everywhere on the lathe, and C, the hypothetical axis, with G01–G03
    /// only (0i-TF/0i-TD operator's manuals, "Polar coordinate interpolation
    /// (G12.1, G13.1)": their sample program's arcs close only so; G00 is
    /// alarm PS0146); the Haas lathe's G112 is "XY to XC interpolation": X
    /// is a radius and Y the hypothetical axis, and the manual's example
    /// retracts at rapid inside the mode. YASNAC follows Fanuc (our
    /// convention: the YASNAC manuals at hand do not describe the mode).
    pub fn polar_interpolation(&self) -> PolarInterpolation {
        self.polar_interpolation.unwrap_or(match self.control {
            Control::Haas => PolarInterpolation::Haas,
            Control::Yasnac | Control::Fanuc | Control::Linuxcnc => PolarInterpolation::Fanuc,
        })
    }

    /// How the D word of the one-block G71/G72 (depth of cut), G74/G75
    /// (relief) and G76 (first depth) reads: see [`DepthWord`].
    pub fn depth_word(&self) -> DepthWord {
        self.depth_word.unwrap_or(match self.control {
            Control::Fanuc => DepthWord::Increments,
            Control::Yasnac | Control::Haas | Control::Linuxcnc => DepthWord::Dimension,
        })
    }
}
