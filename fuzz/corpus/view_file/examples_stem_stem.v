/* The stem seen from the front and a little above, so that its square
   section shows at the top; lit from the upper left. */
projection: perspective
view: 0 dir: 0 -0.35 -1 up: 0 1 0
render mode: shaded
z buffer: on
light: V: -1 1 2
