/* View file (the manual gives none).  It only affects drawing; the derived
   strings do not depend on it.  45 degrees, the usual default turning angle. */
angle increment: 45
initial color: 1
color increment: 1
initial line width: 1
line width increment: 2
