(😀 ‮RTL OVERRIDE‬ ́combining)
G01 X1. F100. (µm)
X١٢
G00 Ｘ１. (fullwidth)
​G00 X2.
