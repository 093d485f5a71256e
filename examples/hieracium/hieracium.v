/* The plant drawn flat, seen from the front: internodes as polygons as
   wide as SetWidth, heads and leaves as flat shapes. */
projection: parallel
line style: polygon
