//! Notes 01 chapter 2: transformations (filled in below).
