//! §2.11–2.22: rotations in every representation (written with the Rotations issue).
