size 1600 1200
mirror xy
fringe eps
picture eps_end.png last
view front
mirror none
sequence shapes.png 1 6 11 16 21      # the deformed shapes side by side (seed fig. 9)
fringe vm
frames anim/vm_ all                   # anim/vm_0001.png ... (folders are made)
history energies.png energy
history elem1.png element 1 eps vm pressure
