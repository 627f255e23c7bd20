This is not a geological model.
Just some words, 1 2 3.
