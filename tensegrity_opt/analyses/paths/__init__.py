"""Loading paths: continuation (natural and arclength), events, bifurcation diagrams, force-deflection curves,
limit loads, stability boundaries, the stability atlas, quasi-static simulation."""
