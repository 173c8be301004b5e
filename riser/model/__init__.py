"""The scene: the line, its sections, ends and attachments, the field specs and the solver settings."""
