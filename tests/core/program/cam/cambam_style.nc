( CamBam style, written for StepDeck's tests )
( Drill pattern in inch: G81 with G98, then G83 pecks with G99 )
G20 G90 G91.1 G64 G40
G0 Z0.2
( T1 : 0.125 )
T1 M6
( Drill1 )
G17
G98
G81 X0.2 Y0.2 Z-0.1 R0.05 F40
X0.4
G80
( Drill2 )
G99 G83 X0.2 Y0.4 Z-0.1 R0.05 Q0.025 F40
G80
G0 Z0.2
M30
