//
// Registry.h : counts the live sensor handlers.
//
// RegistryCount() is declared only as a friend: gcc 3.3 made it visible
// to the rest of the program (friend injection), g++ 4.1 and later find
// it only through an argument of class Registry, and it has none.
//

#ifndef Registry_h_DEFINED
#define Registry_h_DEFINED

class Registry {
public:
    Registry()  { instances++; }
    ~Registry() { instances--; }

    friend int RegistryCount();

private:
    static int instances;
};

#endif // Registry_h_DEFINED
