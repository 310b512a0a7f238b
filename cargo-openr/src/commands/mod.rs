pub mod run;
pub mod sdk;
