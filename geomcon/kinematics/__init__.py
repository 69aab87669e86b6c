"""Whole-cycle kinematics of single-degree-of-freedom linkages of class II (issue 15, "A whole cycle").

A linkage is a crank and a sequence of Assur dyads (RRR, RRP, RPR, PRP) and carried points, each attached to
points and links placed before it (:mod:`.chain`). It is solved over a crank turn with numpy, vectorised over
the crank angles: closed-form dyad positions, and velocities and accelerations from the loop equations
differentiated exactly (:mod:`.dyads`), never finite differences. Each dyad's assembly branch is named
(+1/−1) and followed; a crank angle where a dyad cannot be assembled (a dead point) stops the solve with that
angle, and a change point is reported (:mod:`.cycle`). Outputs: a CSV table, s–v–a plots, an HTML animation
(:mod:`.output`, :mod:`.plots`, :mod:`.animation`); problems are TOML files (:mod:`.problem`).
"""
