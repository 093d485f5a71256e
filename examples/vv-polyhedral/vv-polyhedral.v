/* The subdivided surface seen in perspective from above and to the right,
   flat-shaded (the model sets face normals), lit from the upper left front. */
view: 0 dir: -0.6 -0.5 -1 up: 0 1 0
projection: perspective
render mode: shaded
z buffer: on
light: V: -1 1 2
