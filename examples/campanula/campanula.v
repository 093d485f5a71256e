/* The inflorescence drawn flat, seen from the front: internodes and
   pedicels as polygons as wide as SetWidth, flowers as flat triangles. */
projection: parallel
line style: polygon
