//! cg-scene: the scene format (TOML) and file loading (OBJ, PNG).
