"""Design and control: the strongest chain, preloads (for a pose, a critical load, a stiffness, a trajectory),
load capacity, the arm as a force sensor."""
