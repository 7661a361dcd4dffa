//! Test programs that more than one test file runs (the native tests and
//! the wasm tests, which include this file by its path).

/// A bolt circle of six holes drilled by a WHILE loop (behaviour 20.13,
/// 21.12): hole k at 60k degrees on a radius of 50.
pub const WHILE_BOLT_CIRCLE: &str = "O2000 (BOLT CIRCLE)
G90 G21 G17 G00 Z10.
#1 = 50. (RADIUS)
#2 = 6 (HOLES)
#3 = 0 (HOLES DRILLED)
WHILE [#3 LT #2] DO1
#4 = #3 * 360 / #2
G81 X[#1*COS[#4]] Y[#1*SIN[#4]] Z-5. R2. F100
#3 = #3 + 1
END1
G80 G00 Z10.
M30
";

/// Four holes of a bolt circle, one G65 each (behaviour 21.1): the macro
/// reads the centre (X #24, Y #25), the radius (R #18) and the angle (A #1)
/// from its locals.
pub const G65_BOLT_CIRCLE: &str = "O1000
#1 = 7.
G90 G21 G00 X0 Y0
N40 G65 P9010 X10. Y5. R20. A45.
G65 P9010 X10. Y5. R20. A135.
G65 P9010 X10. Y5. R20. A225.
G65 P9010 X10. Y5. R20. A315.
#101 = #1
M30
O9010
G00 X[#24+#18*COS[#1]] Y[#25+#18*SIN[#1]]
M99
";

/// A large program of feed moves and arcs, with N numbers.
pub fn numbered_program(blocks: usize) -> String {
    let mut program = String::from("N1 G90 G00 X0 Y0\nN2 G01 F100.\n");
    for i in 0..blocks {
        if i % 5 == 4 {
            program.push_str(&format!("N{} G02 X{}. Y0 R30.\n", i + 3, (i % 40) + 2));
        } else {
            program.push_str(&format!("N{} G01 X{}. Y{}.\n", i + 3, i % 40, (i % 3) * 20));
        }
    }
    program
}
