; foldcam: job front for machine grbl-pen-plotter
; expects GRBL laser mode off, $32=0: in laser mode G0 blanks the spindle output that drives the pen
G21
G90
M5
G4 P0.15
G94
; mark
G0 X25 Y5
M3 S1000
G4 P0.15
G1 X31 Y21 F3000
G1 X25 Y37
M5
G4 P0.15
G0 X31 Y21
M3 S1000
G4 P0.15
G1 X51 Y21
M5
G4 P0.15
; change the pen for layer plot, then resume
M0
; plot
M3 S1000
G4 P0.15
G1 X45 Y5
G1 X65 Y5
G1 X71 Y21
M5
G4 P0.15
G0 X45 Y37
M3 S1000
G4 P0.15
G1 X65 Y37
G1 X71 Y21
G1 X51 Y21
G1 X45 Y37
G1 X25 Y37
G1 X5 Y37
G1 X11 Y21
M5
G4 P0.15
G0 X31 Y21
M3 S1000
G4 P0.15
G1 X11 Y21
G1 X5 Y5
G1 X25 Y5
G1 X45 Y5
M5
G4 P0.15
G0 X0 Y0
M2
