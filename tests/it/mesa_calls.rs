//! filled in when the Mesa reference scripts land
