"""Document objects: the parametric AutoBlock feature, write-back, FEM mesh objects."""
