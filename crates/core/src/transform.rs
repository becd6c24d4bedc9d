//! Transform builders (translate, rotate, scale, perspective, look-at) and the application of a
//! matrix to points, vectors and normals, kept apart by name.
