"""The planar beam of Wang et al.: its equations, the problem of a scene, the starting
catenaries and the output."""
