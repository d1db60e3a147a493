!> The one real kind of slidesim: every dependency is double precision.
module base_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int32, int64
  implicit none (type, external)
  private
  public :: wp, int32, int64

  integer, parameter :: wp = real64
end module base_kinds
