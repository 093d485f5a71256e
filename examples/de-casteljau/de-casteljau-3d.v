/* The helix of de-casteljau.l -D THREE_D (its axis z) seen from the side,
   a little from above, z up. */
projection: parallel
view: 0 dir: 0.5 1 -0.4 up: 0 0 1
