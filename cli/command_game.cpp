// cueball game: placeholder
