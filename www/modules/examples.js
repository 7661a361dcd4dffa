// Built-in examples: the seeds' programs with numbers and one CAM-style
// program. Each sets its program, its setup (machine, registers) and,
// where it helps, the plane; its note says what to look at.

export const EXAMPLES = [
  {
    id: 'square',
    title: 'G45–G48 square (seed 000)',
    note: 'The programmed square 80 × 50 is dashed; the actual path runs 6 mm outside it (register 01 = 6): G46 reduces the approach, G47 doubly extends each side. Step through: the arrows and the state panel show the offset distance from the programmed end point.',
    setup: { machine: 'mill', offsets: { '01': 6.0 } },
    program: `(SEED 000: SQUARE WITH G45-G48, REGISTER 01 = 6.)
G90 G00 X-30. Y-20.;
G91 G00 G46 X30. Y20. D01;
G01 G47 X80. F200.;
G47 Y50.;
G47 X-80.;
G47 Y-50.;
G00 G46 X-30. Y-20.;
M30;
`,
  },
  {
    id: 'contour',
    title: 'Contour with a quarter-circle corner (G45, R10)',
    note: 'D01 = 5 (cutter radius): G45 on the quarter circle gives the concentric arc of radius 15, because its ends lie on lines through the centre (seed 003). H02 = 100 lifts Z by the tool length; switch the plane to XZ to see it.',
    setup: { machine: 'mill', offsets: { '01': 5.0, '02': 100.0 } },
    program: `%
O2001 (OUTSIDE CONTOUR 80 X 50 WITH R10 CORNER - TOOL POSITION OFFSET)
(D01 = CUTTER RADIUS 5. / H02 = TOOL LENGTH)
(QUARTER CIRCLE ENDS ON THE AXES THROUGH ITS CENTRE - SEED 003)
N10 G21 G17 G90 G40 G49 G80
N15 T1 M06
N20 S6000 M03
N25 G00 X-20. Y-20.
N30 G43 Z10. H02
N35 G01 Z-3. F200.
N40 G91 G46 X20. Y20. D01
N45 G45 X70. F300.
N50 G45 G03 X10. Y10. J10.
N55 G45 G01 Y40.
N60 G47 X-80.
N65 G47 Y-50.
N70 G00 G46 X-20. Y-20.
N75 G90 G00 Z10.
N80 G49 Z50.
N85 M05
N90 M30
%
`,
  },
  {
    id: 'zero-moves',
    title: 'G45/G46 with X0 (seed 003)',
    note: 'In G91 an axis word of 0 moves by the offset alone: G45 X0 Y0 with D10 = 5 goes +5 along X and Y, G46 X0 with D11 = 3 goes −3 along X. The offset vector stays with every later block until an opposite G45–G48 removes it.',
    setup: { machine: 'mill', offsets: { 10: 5.0, 11: 3.0 } },
    program: `(SEED 003: G45/G46 WITH ZERO MOVEMENT, D10 = 5., D11 = 3.)
G90 G00 X0 Y0;
G91 G01 G45 X0 Y0 D10 F300.;  (+D10 ALONG X AND Y: TO 5, 5)
G00 G46 X0 D11;               (-D11 ALONG X: TO 2, 5)
G01 X20.;                     (NO G45: THE OFFSET VECTOR STAYS)
G45 Y0 D10;                   (+5 ALONG Y)
G90 G00 X0 Y0;
M30;
`,
  },
  {
    id: 'length',
    title: 'G43/G44/G49 tool length offset (seed 001)',
    note: 'Seen from the front (XZ). G43 Z50. H02 with H02 = 15 lands at Z65; G43 H02 without Z moves Z by the offset; the change to H03 = 25 moves by the difference (+10); G44 subtracts; G49 without Z moves back by the old vector.',
    setup: { machine: 'mill', offsets: { '02': 15.0, '03': 25.0 } },
    view: { plane: 'XZ' },
    program: `(SEED 001: TOOL LENGTH OFFSET, H02 = 15., H03 = 25.)
G90 G00 X0 Y0 Z100.;
G43 Z50. H02;           (G43 ADDS H02: Z 50 + 15 = 65)
G01 X30. F300.;
G00 Z80.;               (Z 80 + 15 = 95)
G49 Z80.;               (CANCEL WITH Z: TO THE PROGRAMMED 80)
X50.;
G01 G43 H02;            (NO Z WORD: Z MOVES BY THE OFFSET, +15)
X70.;
H03;                    (H CHANGE: Z MOVES BY 25 - 15 = +10)
X90.;
G00 G44 Z60. H02;       (G44 SUBTRACTS: 60 - 15 = 45)
X110.;
G49;                    (CANCEL WITHOUT Z: BACK BY THE OLD VECTOR)
M30;
`,
  },
  {
    id: 'lathe-seed',
    title: 'Lathe T-code offset (seed 004)',
    note: 'Register 08 = X0.4 Z−0.2. T0108 makes an offset motion at rapid; every later point is 0.2 larger in radius and 0.2 towards the chuck; T0100 alone makes only the cancel motion. Zoom in on a corner to see the arrows.',
    setup: { machine: 'lathe', lathe_offsets: { '08': { x: 0.4, z: -0.2 } } },
    program: `(SEED 004: T-CODE OFFSET, REGISTER 08 = X0.4 Z-0.2)
G50 X120. Z60.;
G00 S800 M03 T0108;     (OFFSET MOTION AT RAPID: X120.4 Z59.8)
X50. Z3.;               (X50.4 Z2.8)
G01 Z-20. F0.2;
X80. Z-35.;
G00 X120. Z60.;
T0100;                  (CANCEL MOTION ONLY: X120. Z60.)
M30;
`,
  },
  {
    id: 'lathe-taper',
    title: 'Lathe taper correction with T codes (seed 004)',
    note: 'The finishing tool runs with offset 02; in N65 the feed move changes to offset 12 (T0212), so its end point moves by the difference of the two offsets: the straight move between them corrects the taper angle. Step to N65 and compare the two paths.',
    setup: {
      machine: 'lathe',
      lathe_offsets: {
        '01': { x: 0.4, z: -0.2 },
        '02': { x: -0.3, z: 0.15 },
        12: { x: -0.3, z: 0.15, x_wear: 0.1 },
      },
    },
    program: `%
O3001 (SHAFT WITH TAPER - T CODE OFFSETS, SEED 004)
N10 G50 X200. Z150.
N15 G00 T0101 (ROUGHING TOOL, OFFSET 01)
N20 G97 S1000 M03
N25 G00 X62. Z2. M08
N30 G90 X56. Z-40. F0.25 (TURNING CYCLE)
N35 X52.
N40 X50.
N45 G00 X200. Z150. T0100
N50 T0202 (FINISHING TOOL, OFFSET 02)
N55 G00 X30. Z2.
N60 G01 Z0 F0.1
N65 G01 U10. W-20. T0212 (TAPER: OFFSET 12 CORRECTS THE ANGLE)
N70 W-20.
N75 G00 U2.
N80 X200. Z150. T0200
N85 M09
N90 M30
%
`,
  },
  {
    id: 'lathe-nose',
    title: 'Lathe profile with tool nose radius compensation (G42, tip 3)',
    note: 'T0101 is an outside turning tool with a nose radius of 0.8 and imaginary tip 3: the program follows the corner of the square round the nose (toward the chuck and the centre line), not the nose centre. G42 keeps the nose right of the path as it cuts toward the chuck. N25 starts up (type A): the nose centre ends 0.8 right of the face’s start, so the imaginary nose is at X-1.600, below the centre line — which is why programs start a face there. On the face (N30) and the diameter (N40) the tool cuts on the programmed line; on the chamfer (N35) and the arc (N45) the imaginary nose would leave material, and G42 moves the tool to cut the true shape: step through and compare the two paths. N55 cancels with G40.',
    setup: {
      machine: 'lathe',
      lathe_offsets: { '01': { x: 0, z: 0, r: 0.8, t: 3 } },
    },
    program: `%
O3002 (PROFILE WITH TOOL NOSE RADIUS COMPENSATION)
(T0101: NOSE RADIUS 0.8, TIP 3 - AN OUTSIDE TURNING TOOL)
N10 G18 G21 G99
N15 T0101
N20 G00 X0 Z2. S1000 M03
N25 G42 G01 Z0 F0.15 (START-UP ONTO THE FACE)
N30 X30. (FACE)
N35 X40. Z-5. (CHAMFER)
N40 Z-20.
N45 G02 X60. Z-30. R10. (CONVEX ARC)
N50 G01 Z-45.
N55 G40 G00 X80. Z5. (CANCEL)
N60 M30
%
`,
  },
  {
    id: 'cutter-contour',
    title: 'Outside contour with arcs (G41 D01, cutter compensation C)',
    note: 'G41 keeps the cutter (D01 = 5) left of the path, so this clockwise contour is cut from outside. N30 starts up (type A): the tool centre ends 5 left of the next block’s start, perpendicular to it. The outside arcs become arcs of radius 15 about the same centres; the slight inside corner after N50 stops at the intersection of the two offset paths; the sharp outside corner at N55 (76°) adds extra vectors round it instead of cutting into the part. N65 cancels with G40 on a move. Step through: the green circle is the cutter, the state panel shows G41, D01 and the mode.',
    setup: { machine: 'mill', offsets: { '01': 5.0 } },
    program: `%
O2002 (OUTSIDE CONTOUR WITH ARCS - CUTTER COMPENSATION C)
(D01 = CUTTER RADIUS 5. / CLOCKWISE, G41 = TOOL LEFT = OUTSIDE)
N10 G21 G17 G90 G40 G49 G80
N15 G00 X-20. Y-20.
N20 Z5.
N25 G01 Z-3. F200.
N30 G41 X0 Y-10. D01 F300. (START-UP)
N35 Y40.
N40 G02 X10. Y50. R10. (OUTSIDE ARC: RADIUS 10 + 5)
N45 G01 X70.
N50 G02 X80. Y40. R10.
N55 G01 X90. Y0 (INSIDE CORNER, THEN A SHARP OUTSIDE ONE)
N60 X-10.
N65 G40 G00 X-20. Y-20. (CANCEL)
N70 Z5.
N75 M30
%
`,
  },
  {
    id: 'cutter-pocket',
    title: 'Pocket: inside corner and an arc too small for the cutter (alarm)',
    note: 'G41 with D01 = 5 runs this pocket counter-clockwise with the cutter inside the wall. At the inside corner X60 Y0 the tool stops where the two offset lines meet (X55 Y5). The next corner is an inside arc of R3: a cutter of radius 5 cannot follow it (its offset radius would be 3 − 5 = −2), so the control stops with its interference alarm (Fanuc PS0041) at N45, and the path is drawn up to it. Make the arc R6. or D01 = 2.5 and the pocket runs to the end.',
    setup: { machine: 'mill', offsets: { '01': 5.0 } },
    program: `%
O2003 (POCKET - INSIDE CORNER AND AN ARC SMALLER THAN THE CUTTER)
(D01 = CUTTER RADIUS 5. / COUNTER-CLOCKWISE, G41 = TOOL INSIDE)
N10 G21 G17 G90 G40 G49 G80
N15 G00 X30. Y20.
N20 Z5.
N25 G01 Z-3. F200.
N30 G41 Y0 D01 F300. (START-UP TO THE WALL)
N35 X60. (INSIDE CORNER: OFFSET LINES MEET)
N40 Y37.
N45 G03 X57. Y40. R3. (R3 IS SMALLER THAN THE CUTTER: ALARM)
N50 G01 X0
N55 Y0
N60 X30.
N65 G40 X30. Y20.
N70 G00 Z5.
N75 M30
%
`,
  },
  {
    id: 'linuxcnc',
    title: 'LinuxCNC program: ; comments, MSG, a tool table, G83 (control LinuxCNC)',
    note: 'An RS274/NGC program as LinuxCNC tutorials write it: `;` comments, numbers without decimal points (X40 is 40 mm), (MSG,…) lines that show as notes at their blocks, T1 M6 G43 reading tool 1 from the tool table (Z 50, D 6; see “Tool table (LinuxCNC)” in the settings), which moves nothing: the position reads from the new tool tip and the next Z move lands offset, and a G83 peck cycle with tool 2 that starts in G99 and backs off 0.254 mm between pecks, as LinuxCNC’s own interpreter does. Choose the Fanuc control to see the same text stop at its first `;` comment.',
    setup: {
      machine: 'mill',
      settings: { control: 'linuxcnc' },
      tool_table: {
        tools: {
          1: { pocket: 1, offsets: [0, 0, 50, 0, 0, 0, 0, 0, 0], diameter: 6, comment: '6 mm end mill' },
          2: { pocket: 2, offsets: [0, 0, 42, 0, 0, 0, 0, 0, 0], diameter: 5, comment: '5 mm drill' },
        },
      },
    },
    program: `%
; plate with a slot and two holes, LinuxCNC 2.9
G21 G17 G90 G40 G49 G80 ; mm, XY plane, absolute, nothing active
(MSG, T1 6 mm end mill: slot)
T1 M6 G43          ; tool 1 of the tool table: length offset 50
G0 X0 Y0 Z5
G0 X10 Y20
G1 Z-2 F150        ; plunge
G1 X40 F400
G3 X40 Y40 R10     ; round end of the slot
G1 X10
G3 X10 Y20 R10
G0 Z5
(MSG, T2 5 mm drill: holes)
T2 M6 G43          ; tool 2: length offset 42
G83 X60 Y20 Z-8 R2 Q3 F120
X60 Y40
G80
G0 Z20
M2
%
`,
  },
  {
    id: 'cam',
    title: 'CAM-style pocket and drilling (G43, G83)',
    note: 'A post-processor style program: G28 returns, tool changes with G43 H01 (120.5) and H02 (95.3 − 0.05 wear), a pocket loop with an arc, then G83 peck drilling. See the length offsets in the XZ plane and the wear in the offset table (offset memory B: a geometry and a wear per number).',
    setup: {
      machine: 'mill',
      settings: { offset_memory: 'B' },
      start: { x: 0, y: 0, z: 50 },
      reference: { x: 0, y: 0, z: 50 },
      offsets: { '01': 120.5, '02': { geometry: 95.3, wear: -0.05 } },
    },
    program: `%
O1001 (POCKET AND DRILL - FANUC MILL POST STYLE)
(T1 D=10. FLAT END MILL - H01)
(T2 D=6.8 DRILL - H02)
N10 G90 G94 G17 G49 G40 G80
N15 G21
N20 G28 G91 Z0.
N25 G90
(POCKET 20 X 10 ROUGHING LOOP, DEPTH 5)
N30 T1 M06
N35 S8000 M03
N40 G54
N45 M08
N50 G00 X20. Y15.
N55 G43 Z15. H01
N60 G00 Z5.
N65 G01 Z-5. F300.
N70 X30. F800.
N75 Y20.
N80 X10.
N85 Y10.
N90 X30.
N95 Y15.
N100 G03 X25. Y20. R5.
N105 G01 X20.
N110 G00 Z15.
N115 M09
N120 G28 G91 Z0.
N125 G90 G49
(DRILL 4 HOLES WITH PECKING)
N130 T2 M06
N135 S2500 M03
N140 G54
N145 G00 X5. Y5.
N150 G43 Z15. H02
N155 G98 G83 X5. Y5. Z-12. R2. Q3. F150.
N160 X35.
N165 Y25.
N170 X5.
N175 G80
N180 G28 G91 Z0.
N185 G90 G49
N190 M05
N195 M30
%
`,
  },
];

export const DEFAULT_EXAMPLE = EXAMPLES[0];

export function exampleById(id) {
  return EXAMPLES.find((e) => e.id === id) ?? null;
}
