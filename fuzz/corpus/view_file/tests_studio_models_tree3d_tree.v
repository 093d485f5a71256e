/* Cylinders, seen in perspective, lit from the upper left. */
projection: perspective
line style: cylinder
contour sides: 8
render mode: shaded
z buffer: on
light: V: -1 1 2
