/* Lit, depth-tested cylinders: the costly way to draw the plant. */
projection: perspective
line style: cylinder
contour sides: 8
render mode: shaded
z buffer: on
light: V: -1 1 2
