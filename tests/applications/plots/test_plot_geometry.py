"""The chain's drawing geometry: spring lengths, tip, joints and triangles against the model."""

from __future__ import annotations

import numpy as np
import pytest

import tensegrity_opt as to
from tensegrity_opt.applications import plots
from tensegrity_opt.errors import InvalidParameterError


def test_chain_geometry_reproduces_spring_lengths_and_tip():
    rng = np.random.default_rng(3)
    m = to.Manipulator([to.Segment(0.6, 1.0, 1.0, 1.5), to.Segment(1.2, 0.7, (1.0, 2.0), (1.0, 1.3)),
                        to.Segment(0.9, 1.4, 2.0, 2.5), to.Segment(0.5, 0.5, 1.0, 1.0), to.Segment(1.0, 1.0)])
    for q in [np.zeros(m.n), *(rng.uniform(-0.95, 0.95, m.n) * m.joint_limits for _ in range(20))]:
        g = plots.chain_geometry(m, q)
        L1, L2 = m.spring_lengths(q)
        d = np.linalg.norm(g["springs"][:, :, 1] - g["springs"][:, :, 0], axis=-1)
        assert np.allclose(d[:, 0], L1, rtol=1e-12, atol=1e-12)
        assert np.allclose(d[:, 1], L2, rtol=1e-12, atol=1e-12)
        assert np.allclose(g["centerline"][-1], m.tip(q), atol=1e-12)
        assert np.allclose(g["tip"], m.tip(q), atol=1e-12)
        assert np.allclose(g["joints"][0], [m.base_length, 0.0])
        assert np.allclose(np.linalg.norm(np.diff(g["joints"], axis=0), axis=1), m.link_lengths[:-1])
        # each triangle: apex at the joint, base corners at distance c = hypot(a, b), base length 2a
        tri = g["triangles"]
        assert np.allclose(tri[:, :, 0], g["joints"][:, None, :])
        c = np.hypot(m.a, m.b)
        for corner in (1, 2):
            assert np.allclose(np.linalg.norm(tri[:, :, corner] - tri[:, :, 0], axis=-1), c[:, None])
        assert np.allclose(np.linalg.norm(tri[:, :, 1] - tri[:, :, 2], axis=-1), 2 * m.a[:, None])
        # springs join the triangles' corners (spring 1: left corners, spring 2: right corners)
        assert np.allclose(g["springs"][:, 0, 0], tri[:, 0, 1]) and np.allclose(g["springs"][:, 0, 1], tri[:, 1, 1])
        assert np.allclose(g["springs"][:, 1, 0], tri[:, 0, 2]) and np.allclose(g["springs"][:, 1, 1], tri[:, 1, 2])
    straight = plots.chain_geometry(m, np.zeros(m.n))
    assert np.allclose(straight["tip"], [m.straight_length, 0.0])
    with pytest.raises(InvalidParameterError):
        plots.chain_geometry(m, np.zeros(3))
