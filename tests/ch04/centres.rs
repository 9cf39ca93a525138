//! §4.15–4.18: screw axis, IVCR, IACR, Chasles, rolling.
