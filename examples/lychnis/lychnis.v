/* The inflorescence in 3D, seen from the front and a little above:
   internodes as cylinders, flowers as spheres, lit from the upper left. */
projection: perspective
view: 0 dir: 0 -0.3 -1 up: 0 1 0
line style: cylinder
contour sides: 8
render mode: shaded
z buffer: on
light: V: -1 1 2
