//! C library names used without their header. gcc 3.3's C++ headers included the C
//! library's on the way (`<string>` and every container through `<bits/stl_algobase.h>`:
//! `<cstring>`, `<cstdlib>`, `<climits>`; the iostreams: `<cstdio>`, `<cctype>`; the
//! thread layer: `<ctime>`), so AIBO code called `memcpy`, `atoi` or `printf` having
//! included only `<string>` or `<iostream.h>`. gcc 4.3 cut those inclusions ("header
//! dependency streamlining" in its porting notes). The repair compiles the unit with the
//! C header that declares the name included first (`-include`), which moves no line.

/// `(C header, names it declares)`: the ones gcc 3.3-era code used undeclared.
const TABLE: &[(&str, &[&str])] = &[
    (
        "string.h",
        &[
            "memcpy",
            "memmove",
            "memset",
            "memcmp",
            "memchr",
            "strcpy",
            "strncpy",
            "strcat",
            "strncat",
            "strcmp",
            "strncmp",
            "strcasecmp",
            "strncasecmp",
            "strlen",
            "strchr",
            "strrchr",
            "strstr",
            "strtok",
            "strtok_r",
            "strdup",
            "strerror",
            "strspn",
            "strcspn",
            "strpbrk",
            "strcoll",
            "strxfrm",
            "bzero",
            "bcopy",
            "bcmp",
            "index",
            "rindex",
        ],
    ),
    (
        "stdlib.h",
        &[
            "atoi",
            "atol",
            "atof",
            "strtol",
            "strtoul",
            "strtod",
            "strtof",
            "malloc",
            "calloc",
            "realloc",
            "free",
            "exit",
            "abort",
            "atexit",
            "abs",
            "labs",
            "div",
            "ldiv",
            "rand",
            "srand",
            "random",
            "srandom",
            "qsort",
            "bsearch",
            "getenv",
            "setenv",
            "putenv",
            "system",
            "EXIT_SUCCESS",
            "EXIT_FAILURE",
            "RAND_MAX",
        ],
    ),
    (
        "stdio.h",
        &[
            "printf",
            "fprintf",
            "sprintf",
            "snprintf",
            "vprintf",
            "vfprintf",
            "vsprintf",
            "vsnprintf",
            "scanf",
            "fscanf",
            "sscanf",
            "fopen",
            "fclose",
            "fread",
            "fwrite",
            "fgets",
            "fputs",
            "fgetc",
            "fputc",
            "getc",
            "putc",
            "puts",
            "putchar",
            "getchar",
            "fflush",
            "fseek",
            "ftell",
            "rewind",
            "feof",
            "ferror",
            "clearerr",
            "perror",
            "remove",
            "rename",
            "tmpfile",
            "setvbuf",
            "setbuf",
            "fileno",
            "FILE",
            "EOF",
            "stdin",
            "stdout",
            "stderr",
            "SEEK_SET",
            "SEEK_CUR",
            "SEEK_END",
            "BUFSIZ",
        ],
    ),
    (
        "limits.h",
        &[
            "CHAR_BIT",
            "SCHAR_MIN",
            "SCHAR_MAX",
            "UCHAR_MAX",
            "CHAR_MIN",
            "CHAR_MAX",
            "SHRT_MIN",
            "SHRT_MAX",
            "USHRT_MAX",
            "INT_MIN",
            "INT_MAX",
            "UINT_MAX",
            "LONG_MIN",
            "LONG_MAX",
            "ULONG_MAX",
        ],
    ),
    (
        "ctype.h",
        &[
            "isalnum", "isalpha", "iscntrl", "isdigit", "isgraph", "islower", "isprint", "ispunct", "isspace", "isupper", "isxdigit", "tolower", "toupper",
            "isascii",
        ],
    ),
    ("time.h", &["time", "clock", "difftime", "localtime", "gmtime", "mktime", "strftime", "ctime", "asctime", "CLOCKS_PER_SEC"]),
    ("errno.h", &["errno"]),
    (
        "math.h",
        &[
            "sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log", "log10", "pow", "fabs", "floor", "ceil", "fmod", "sinh", "cosh",
            "tanh", "hypot", "rint", "sqrtf", "sinf", "cosf", "tanf", "atan2f", "fabsf", "floorf", "ceilf", "powf", "expf", "logf", "M_PI", "M_PI_2", "M_PI_4",
            "M_E", "HUGE_VAL",
        ],
    ),
    // What newlib's headers declared and glibc's lack: the SDK's header of the robot's C
    // library has them (the one every OPEN-R header includes).
    (
        NEWLIB,
        &[
            "strlwr", "strupr", "strlcpy", "strlcat", "strcmpi", "stricmp", "strncmpi", "strnicmp", "atoff", "ecvtf", "fcvtf", "gcvtf", "ecvtbuf", "fcvtbuf",
            "cfree", "M_TWOPI", "M_3PI_4", "M_SQRTPI", "M_LN2LO", "M_LN2HI", "M_SQRT3", "M_IVLN10", "M_LOG2_E", "M_INVLN2",
        ],
    ),
];

/// The SDK's header of the robot's C library (`sdk-payload/include/openr_newlib.h`).
pub(crate) const NEWLIB: &str = "openr_newlib.h";

/// Whether `name` of [`TABLE`] is a function (a macro, a constant, `errno` and the
/// standard streams are not): it is only taken for libc's where it is called.
pub(crate) fn is_function(name: &str) -> bool {
    !(name.bytes().all(|b| b.is_ascii_uppercase() || b.is_ascii_digit() || b == b'_') || matches!(name, "errno" | "stdin" | "stdout" | "stderr"))
}

/// The C header declaring `name`, if it is one of [`TABLE`]'s.
fn header_of(name: &str) -> Option<&'static str> {
    TABLE.iter().find(|(_, names)| names.contains(&name)).map(|(h, _)| *h)
}

/// For g++'s "'memcpy' was not declared in this scope" or "'memcpy' is not a member of
/// 'std'": the name and the header to include first (`<string.h>`, or `<cstring>` for
/// a name written `std::memcpy`).
pub(crate) fn missing(msg: &str) -> Option<(String, String)> {
    let m = super::diag::ascii_quotes(msg);
    let name = m.strip_prefix('\'')?.split('\'').next()?;
    let header = header_of(name)?;
    if m.contains("' was not declared in this scope") {
        Some((name.to_string(), header.to_string()))
    } else if m.contains("' is not a member of 'std'") && header != NEWLIB {
        Some((format!("std::{name}"), format!("c{}", header.trim_end_matches(".h"))))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_map_to_the_header_gcc_3_3_brought() {
        assert_eq!(missing("\u{2018}memcpy\u{2019} was not declared in this scope"), Some(("memcpy".into(), "string.h".into())));
        assert_eq!(missing("'atoi' was not declared in this scope; did you mean 'atol'?"), Some(("atoi".into(), "stdlib.h".into())));
        assert_eq!(missing("'strlen' is not a member of 'std'; did you mean 'mbrlen'?"), Some(("std::strlen".into(), "cstring".into())));
        assert_eq!(missing("'INT_MAX' was not declared in this scope"), Some(("INT_MAX".into(), "limits.h".into())));
        assert_eq!(missing("'M_PI' was not declared in this scope"), Some(("M_PI".into(), "math.h".into())));
        assert_eq!(missing("'strlwr' was not declared in this scope"), Some(("strlwr".into(), NEWLIB.into())));
        assert_eq!(missing("'frobnicate' was not declared in this scope"), None);
        assert_eq!(missing("'memcpy' does not name a type"), None);
        assert_eq!(missing("'memcpy' is not a member of 'Foo'"), None);
    }
}
