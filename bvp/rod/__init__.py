"""The 3D rod: the planar beam out of its plane (equations, problem, output)."""
