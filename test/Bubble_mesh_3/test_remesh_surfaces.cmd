modelA1.ml
