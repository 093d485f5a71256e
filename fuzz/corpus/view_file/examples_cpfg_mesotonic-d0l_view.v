/* View file (the notes give none).  It only affects
   drawing; the derived strings do not depend on it.  The notes' default turning
   angle is 45 degrees (theory paper, line 754). */
angle increment: 45
initial color: 1
color increment: 1
initial line width: 1
line width increment: 2
