executable: honda81 honda.par
communication type: pipes
turtle position: %g %g %g
