/* The leaf drawn flat, seen from the front: rachis and petiolules as
   polygons as wide as SetWidth, leaflets as flat rhombi. */
projection: parallel
line style: polygon
