"""fdmResistance: theoretical two-sphere and sphere-wall resistance functions
for the sub-grid (SG) lubrication correction, and the table generator.

Modules: twoSphere (twin-multipole series, Jeffrey & Onishi 1984, Jeffrey
1992), wall (lubrication forms, Chaoui & Feuillebois 2003), writeTables
(OpenFOAM-dictionary tables in data/resistance), test_resistance (unittest).
X^P (pressure moments): near-contact forms only, O(1) constants unknown (0).
"""
