//! The OPEN-R host runtime and the files of the SDK root it pairs with.
//!
//! [`sdk_files`] carries the OPEN-R headers (`include/`, installed as
//! `OPEN_R/include`) and the C++ surface (`cxx/`, compiled into the `OPEN_R/lib`
//! archives that every object links), both written from the clean-room spec.

pub mod sdk_files {
    //! Files embedded at build time: `(path relative to its tree, contents)`.
    include!(concat!(env!("OUT_DIR"), "/sdk_files.rs"));
}
