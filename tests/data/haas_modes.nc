%
O5001 (HAAS MODES - POCKETS, SKIP, INVERSE TIME)
(positions by hand: register 01 = 3., read by D01 and H01)
N10 G21 G17 G90 G40 G49 G80 G64
N15 G187 P3 E0.02
N20 T1 M06
N25 G00 G54 X20. Y10. S2000 M03
N30 G43 Z5. H01                  (actual Z 8.)
N35 G61
N40 G01 Z0 F300.                 (actual Z 3.)
N45 G12 I10. K16. Q3. Z-2. D01 F200. (circles 10, 13, 16; tool centre 7, 10, 13; ends X20. Y10. Z-2.)
N50 G13 G91 Z-1. I8. L2          (D01 still selected: tool centre radius 5; Z-3., Z-4.)
N55 G90 G64
N60 G93 G01 X40. F4.             (a 15 s move)
N65 G94 G31 X50. Y0 F100.
N70 G09 G01 Y-10.
N75 G05.1 Q1
N80 G08 P1
N85 G00 Z50.
N90 M30
%
