//! `stub.cfg` parser and stub generator: the host flavour of Sony's `stubgen2`
//! (object-model 1.1, 1.2).
//!
//! A `stub.cfg` names the core class of an OPEN-R object, its subject (sending) and
//! observer (receiving) services and extra entry points. From it `stubgen2` writes
//! `def.h`, `entry.h`, `<ObjectName>Stub.h` and `<ObjectName>Stub.cc`, which give every
//! entry point a selector and fill the `ObjectEntryTable` the runtime dispatches through.
//!
//! All checks happen before anything is written; errors read `<file>:<line>: <message>`
//! and keep Sony's message texts where Sony had one. What Sony's tool accepted but is
//! dubious (a SubName used twice) is accepted too and reported by [`warnings`].
//!
//! ```
//! let cfg = stubgen::parse_str("stub.cfg", "\
//! ObjectName : SampleSubject
//! NumOfOSubject : 1
//! NumOfOObserver : 1
//! Service : \"SampleSubject.SendString.char.S\", null, Ready()
//! Service : \"SampleSubject.DummyObserver.DoNotConnect.O\", null, null
//! ").unwrap();
//! assert_eq!(cfg.object_name, "SampleSubject");
//! assert_eq!(cfg.subjects[0].func2.as_deref(), Some("Ready"));
//!
//! let files = stubgen::generate(&cfg).unwrap();
//! let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
//! assert_eq!(names, ["def.h", "entry.h", "SampleSubjectStub.h", "SampleSubjectStub.cc"]);
//! assert!(files[0].1.contains("const int sbjSendString = 0;"));
//! assert!(files[1].1.contains("const ::longword numOfBasicEntries = 8;"));
//! assert!(files[3].1.contains("StubFuncDefine_Ready(0, Ready)"));
//! assert!(stubgen::summary(&cfg).starts_with("Object = SampleSubject\nnumOfSubject  = 1\n"));
//!
//! let err = stubgen::parse_str("stub.cfg", "ObjectName : X\nNumOfOSubject : 2\n").unwrap_err();
//! assert_eq!(err.to_string(),
//!     "stub.cfg:2: Inconsitency found between service and numOfOSubject. (NumOfOSubject = 2, \
//!      but 0 subject service(s) found; Service lines whose name is not \
//!      \"<Obj>.<Sub>.<Data>.S\" are ignored)");
//! ```

mod cli;
mod error;
mod generate;
mod parse;
mod warn;

pub use cli::run_stubgen2;
pub use error::{Error, ErrorKind};
pub use generate::{generate, output_names, summary, write_outputs};
pub use parse::{is_identifier, parse_files, parse_str, Service, ServiceKind, StubCfg};
pub use warn::{warnings, Warning};
