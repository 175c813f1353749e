"""fdmSuspension post-processing helpers (Python 3, numpy; Debian packages)."""
