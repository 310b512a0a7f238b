//
// Tracker.h : turns a target's position in the image into head motion.
//
// As in Sony's BallTrackingHead7 sample, the header repeats a parameter
// name ("delta_pan" twice): gcc 3.3 accepted it, g++ 4 and later reject
// it even with -fpermissive. The definitions in Tracker.cc use the right
// names.
//

#ifndef Tracker_h_DEFINED
#define Tracker_h_DEFINED

class Tracker {
public:
    Tracker(double gain);

    void Track(double x, double y, double* delta_pan, double* delta_pan);
    void Limit(double max, double* delta_pan, double* delta_pan) const;

private:
    double gain;
};

#endif // Tracker_h_DEFINED
