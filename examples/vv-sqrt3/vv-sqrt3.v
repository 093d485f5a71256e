/* The subdivided surface seen in perspective from above and to the right,
   smooth-shaded (the model sets vertex normals), lit from the upper left front. */
view: 0 dir: -0.6 -0.5 -1 up: 0 1 0
projection: perspective
render mode: shaded
z buffer: on
light: V: -1 1 2
