"""MoorDyn v2 decks, an input format: :mod:`.deck` (the text read into tables,
``DeckError`` naming the deck line), :mod:`.scene_from_deck` (deck -> scene) and
:mod:`.deck_from_scene` (scene -> deck: equivalent sections, and the deck's text)."""
