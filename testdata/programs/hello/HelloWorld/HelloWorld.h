//
// HelloWorld.h
//
// The core class of the HelloWorld object. Because the stub of this
// object is written by hand (HelloWorldStub.cc) there is no def.h and
// no subject/observer: OObject.h is the only header we need.
//

#ifndef HelloWorld_h_DEFINED
#define HelloWorld_h_DEFINED

#include <OPENR/OObject.h>

class HelloWorld : public OObject {
public:
    HelloWorld();
    virtual ~HelloWorld() {}

    virtual OStatus DoInit   (const OSystemEvent& event);
    virtual OStatus DoStart  (const OSystemEvent& event);
    virtual OStatus DoStop   (const OSystemEvent& event);
    virtual OStatus DoDestroy(const OSystemEvent& event);
};

#endif // HelloWorld_h_DEFINED
