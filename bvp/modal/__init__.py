"""Natural modes about the BVP static state: the linearised equations, the end conditions,
the eigen-solver."""
