//! Typed indices into a [`CreasePattern`](super::CreasePattern).
//!
//! Indices are `u32` newtypes: a pattern holds at most `u32::MAX` vertices, edges or faces,
//! which importers enforce with an error. Using distinct types keeps a vertex index from being
//! passed where an edge index is meant.

use std::fmt;

macro_rules! id_type {
    ($(#[$doc:meta])* $name:ident, $prefix:literal) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Default, serde::Serialize, serde::Deserialize)]
        #[serde(transparent)]
        pub struct $name(pub u32);

        impl $name {
            /// The index as `usize`, for indexing a `Vec`.
            #[inline]
            pub fn index(self) -> usize {
                self.0 as usize
            }

            /// Builds an id from a `usize` index.
            ///
            /// # Panics
            /// If `i` does not fit in `u32`; importers reject such sizes before this is reached.
            #[inline]
            pub fn new(i: usize) -> Self {
                Self(u32::try_from(i).expect("index exceeds u32::MAX"))
            }
        }

        impl fmt::Display for $name {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                write!(f, concat!($prefix, "{}"), self.0)
            }
        }
    };
}

id_type!(
    /// Index of a vertex.
    VertexId,
    "v"
);
id_type!(
    /// Index of an edge.
    EdgeId,
    "e"
);
id_type!(
    /// Index of a face.
    FaceId,
    "f"
);
