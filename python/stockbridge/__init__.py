"""stockbridge: Stockbridge damper impedance from a distributed Masing cable model.

The numerics live in the C++ library; this package binds it (``stockbridge._core``,
built by the CMake project) and adds plots (``python3 -m stockbridge.plot``).

    import stockbridge as sb
    damper = sb.load_damper("examples/sauter2003.toml")
    z = sb.impedance(damper, [10.0, 20.0], velocity=[0.2, 0.05])
"""

try:
    from ._core import (Cable, Damper, Error, InputError, InvalidParameter, NumericalError, cycle,  # noqa: F401
                        identify_global, identify_local, impedance, load_cable, load_damper, make_cable,
                        make_damper, response, strand_bounds)
except ImportError:  # the plots work from the source tree without the compiled module
    pass
