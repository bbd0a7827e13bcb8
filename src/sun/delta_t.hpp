// ΔT = TT − UT, the difference between the uniform time the ephemerides run on and the Earth's
// rotation: Espenak and Meeus's polynomials (NASA, "Polynomial expressions for Delta T", 2006)
// from 1800 to 2150 and their parabola outside. The Sun moves 0.04″ per second of ΔT, so an
// error of seconds in a future year moves it by thousandths of a degree at most.
#pragma once

namespace globe::sun {

// decimalYear: 2024.5 is the middle of 2024.
double deltaTSeconds(double decimalYear);

}  // namespace globe::sun
