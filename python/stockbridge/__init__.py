"""stockbridge: Stockbridge damper impedance from a distributed Masing cable model.

The numerics live in the C++ library and the ``stockbridge`` program; this package
holds what is Python's to do: ``python3 -m stockbridge.plot`` draws the program's
CSV files with matplotlib.
"""
