"""OrcaFlex text data files in and out: :mod:`.scene_from_model` (``import-orcaflex``: one
line of a model -> a scene) and :mod:`.model_from_scene` (``export-orcaflex``: a scene ->
a model OrcaFlex loads). Reading needs PyYAML (the optional extra ``[orcaflex]``);
writing does not."""
