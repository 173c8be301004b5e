"""The line and the scene composing it all: line types and segments, sections, ends and
attachments, the line's plane, the solver settings and the key tables of the docs."""
