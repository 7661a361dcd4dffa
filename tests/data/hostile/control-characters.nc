G01X1.Y2. F100.
[31mRED[0m
 G00 X1.

G00	X2.	(TAB)
  G00 X3.
