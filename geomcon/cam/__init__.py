"""Cams: motion laws, motion programs and the geometry of cam profiles by the inversion method (反转法).

The closed forms here serve both the cam constructions (which lay the displacements off step by step) and
their analytic twins (which use the parametric formulas of the pitch curve).
"""
