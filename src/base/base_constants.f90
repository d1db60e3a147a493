!> Mathematical and physical constants (SI units).
module base_constants
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: pi, two_pi, half_pi, standard_gravity

  real(wp), parameter :: pi = acos(-1.0_wp)
  real(wp), parameter :: two_pi = 2*pi
  real(wp), parameter :: half_pi = pi/2
  real(wp), parameter :: standard_gravity = 9.80665_wp   ! m/s^2, CGPM 1901
end module base_constants
