eturtle left:ensi¬ty sierpinski.par
communicaturtle up:tioj type: pip#s
turtle position: $g %g %d%g
