"""The model: segments and chains as numpy objects (geometry, energy, torque, joint range).

No solver and no CasADi here: :class:`~.segment.Segment` (one dual-triangle segment, eqs. 1-4 of
the paper), :class:`~.manipulator.Manipulator` (the serial chain, eq. 5-7: tip, energy, gradient,
the physical joint range) and :mod:`.shapes` (the paper's shape labels). Everything above this
layer takes a ``Manipulator``.
"""
