"""The VFIFE's linearisation about its static state (tangent stiffness and mass) and its
natural modes."""
