!> Fixed quadrature rules shared by the layers below.
!>
!> gl8_x, gl8_w: the 8-point Gauss-Legendre rule on [-1, 1] (exact for
!> polynomials of degree <= 15): int_a^b f ~ (b - a)/2 sum_i gl8_w(i)
!> f((a + b)/2 + (b - a)/2 gl8_x(i)). The values are the usual tabulated
!> ones to 16 digits.
module numerics_quadrature
  use base_kinds, only: wp
  implicit none (type, external)
  private

  real(wp), parameter, public :: gl8_x(8) = [-0.9602898564975363_wp, -0.7966664774136267_wp, &
    -0.5255324099163290_wp, -0.1834346424956498_wp, 0.1834346424956498_wp, &
    0.5255324099163290_wp, 0.7966664774136267_wp, 0.9602898564975363_wp]
  real(wp), parameter, public :: gl8_w(8) = [0.1012285362903763_wp, 0.2223810344533745_wp, &
    0.3137066458778873_wp, 0.3626837833783620_wp, 0.3626837833783620_wp, &
    0.3137066458778873_wp, 0.2223810344533745_wp, 0.1012285362903763_wp]
end module numerics_quadrature
