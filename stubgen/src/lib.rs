//! stub.cfg parser and generator (object-model 1.1, 1.2).
