/* A flat drawing: pixel lines, viewed from the front. */
projection: parallel
line style: pixel
scale: 0.9
