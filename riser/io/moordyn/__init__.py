"""MoorDyn v2 input files ("decks"), an input format read as MoorDyn-C 2.7 reads it:
:mod:`.tokens` (``DeckError`` naming the deck line; numbers as MoorDyn reads them),
:mod:`.deck` (the text read into tables, and its sections and option names),
:mod:`.options` (the OPTIONS as MoorDyn-C reads them: its defaults, what a scene honours,
refuses or does not carry), :mod:`.scene_from_deck` (deck -> scene) and
:mod:`.deck_from_scene` (scene -> deck: equivalent sections, and the deck's text) and
:mod:`.waves` (WaveKin 7's wave_frequencies.txt: MoorDyn-C's summed wave components read
into a scene's trains and written from its components)."""
