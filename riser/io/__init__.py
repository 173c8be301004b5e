"""File formats of the model: :mod:`.scene_file` (a TOML scene file -> a validated
:class:`~riser.model.scene.Scene`), :mod:`.toml_table` (typed, path-aware reading of a TOML
table, one-line errors), :mod:`.toml_text` (a scene's TOML text) and :mod:`.moordyn`
(MoorDyn v2 decks in and out)."""
