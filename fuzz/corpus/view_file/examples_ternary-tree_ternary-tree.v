/* A 3D tree: branches as cylinders, seen from the side, lit from the front left. */
projection: perspective
line style: cylinder
contour sides: 8
render mode: shaded
z buffer: on
light: V: -1 1 2
tropism: T: 0 -1 0 E: 0.27
