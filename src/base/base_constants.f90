!> Mathematical and physical constants (SI units).
module base_constants
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: pi, two_pi, half_pi, standard_gravity, dry_air_density

  real(wp), parameter :: pi = acos(-1.0_wp)
  real(wp), parameter :: two_pi = 2*pi
  real(wp), parameter :: half_pi = pi/2
  real(wp), parameter :: standard_gravity = 9.80665_wp   ! m/s^2, CGPM 1901
  !> kg/m^3, dry air at 20 C and 101.325 kPa: the ideal gas p M/(R T) with
  !> the molar mass of dry air M = 28.9644 g/mol (U.S. Standard Atmosphere
  !> 1976) and R = 8.314462618 J/(mol K) (CODATA 2018), 1.20408 to 5 digits
  real(wp), parameter :: dry_air_density = 1.2041_wp
end module base_constants
