//! §4.19–4.21: worked examples and problems.
