# README pictures of the oblique rod (seed example 2, paper fig. 12-13).
# Run in the run folder (out/seed/oblique_rod/), e.g. by tools/make-readme-pictures.sh:
#   postimpact d3plot -d DIR -c tools/pictures/oblique_rod.cmd
# Half model (y >= 0): mirrored across y = 0 to the whole rod.  The wall (not drawn) is the
# plane sin(10) x + cos(10) z = 0 through the origin, falling toward +x.
size 1000 750
plotsize 1000 625
mirror y
fringe eps
# fixed range: above 1 (up to 2.1, in the first contact element 16) is drawn red
range 0 1
bands 10

# fig. 12: successive deformed shapes every 600 us, seen along the symmetry normal (-y)
# (no element edges: at this scale the rod is a few pixels wide and the edges would hide it)
view front
edges off
size 1000 650
sequence oblique_rod_shapes.png t=0 t=6e-4 t=1.2e-3 t=1.8e-3 t=2.4e-3
size 1000 750
edges on

# fig. 13: the deformed rod at 2400 us in perspective
view -60 25
picture oblique_rod_2400us.png t=2.4e-3

# time histories (every 5 us): the first contact node 33, the top axis node 4788
open d3thdt
title Oblique rod: first contact node 33 and top axis node 4788
history oblique_rod_nodes.png node 33 vx vz dx dz node 4788 vx vz dz
title Oblique rod (half model): energies
plotsize 1000 750
history oblique_rod_energies.png energy
