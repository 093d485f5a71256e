executable: density sierpinski.par
communication type: pipes
turtle position: %g %g %g
