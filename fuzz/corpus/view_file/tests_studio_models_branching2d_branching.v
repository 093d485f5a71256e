/* Seen from the front, lines one pixel wide. */
projection: parallel
