"""Analytic twins: closed-form solutions written independently of the constructions.

These modules import nothing from :mod:`geomcon.geometry` or :mod:`geomcon.scene`: they are the second,
separate route that every construction is checked against.
"""
