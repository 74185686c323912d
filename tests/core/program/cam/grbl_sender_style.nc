%
O1001 (POCKET CORNERS)
(A GRBL sender's file in a Fanuc-style wrapper, written for StepDeck's tests: the sender's)
($ lines, arcs with K0.000 as FreeCAD's grbl post writes them, a block delete line, and the)
(post's trailer after the closing percent)
$X
$H
$32=0
G90 G94 G17
G21
G0 Z5.000
/M0 (check the clamps: skipped while block delete is on)
G0 X3.000 Y3.000 S12000 M3
G1 Z-0.500 F240.000
G1 X9.000 Y3.000 F480.000
G3 X11.000 Y5.000 I0.000 J2.000 K0.000
G1 X11.000 Y7.000
G3 X9.000 Y9.000 I-2.000 J0.000 K0.000
G1 X3.000 Y9.000
G1 X3.000 Y3.000
G0 Z5.000
M5
M30
%
(the post's trailer: never read)
G0 X50.000 Y50.000
