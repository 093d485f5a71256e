/* A compound leaf seen from above its blade: leaflets as the Bezier
   surface leaf.s (surface 0, unit length, tessellated 8 x 8 per patch),
   rachis and petiole as thin cylinders, lit from the upper left. */
projection: parallel
line style: cylinder
contour sides: 8
render mode: shaded
z buffer: on
light: V: -1 1 2
surface: leaf.s 1 8 8
