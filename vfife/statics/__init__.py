"""The VFIFE's static equilibrium: dynamic relaxation with mesh sequencing, Newton near
equilibrium, starting shapes."""
