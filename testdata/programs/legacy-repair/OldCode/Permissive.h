//
// Permissive.h : gcc 3.3 habits that -fpermissive (which the SDK's
// compiler passes) still accepts, with a warning: nothing is repaired.
//
//  - "Servo::" inside class Servo (extra qualification)
//  - a default argument repeated where the function is defined
//  - a member of a dependent base called without "this->"
//

#ifndef Permissive_h_DEFINED
#define Permissive_h_DEFINED

class Servo {
public:
    Servo::Servo(int id);
    int Servo::Id() const;
    int Scaled(int value, int scale = 2) const;

private:
    int id;
};

template <class T>
struct Doubler {
    T Twice(T v) const { return v + v; }
};

template <class T>
struct Quadrupler : public Doubler<T> {
    T Four(T v) const { return Twice(Twice(v)); }
};

int ServoCount();

#endif // Permissive_h_DEFINED
