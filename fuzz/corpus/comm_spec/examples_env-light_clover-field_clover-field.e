executable: clover -e clover-field.e clover.par
communication type: pipes
turtle position: %g %g %g
