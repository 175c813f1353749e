"""Pre-processing for fdmSuspension cases (particle packings)."""
