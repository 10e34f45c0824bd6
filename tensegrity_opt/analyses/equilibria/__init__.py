"""Equilibria: one equilibrium, the least-energy one, every one, rest shapes, stability, buckling, stiffness,
the energy landscape."""
