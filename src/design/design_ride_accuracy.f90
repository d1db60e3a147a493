!> The ride's accuracy presets (issue 29, point 2): the tolerances of both
!> integrators of a ride (the rider's and the water's), named by what they
!> guarantee for the ride report. Each guarantee is measured, not derived:
!> bench/accuracy_study.py runs every shipped ride at the preset and at
!> rtol 1e-12 and compares every number of the report (docs/accuracy.md);
!> a preset's `within` is the bound it shows with a margin (the measured
!> worst is in the docs). A new slide or rider far from the shipped ones is
!> not covered by that measurement: the study says how to check it.
module design_ride_accuracy
  use base_kinds, only: wp
  implicit none (type, external)
  private
  public :: accuracy_preset_t, accuracy_presets, find_accuracy_preset

  type :: accuracy_preset_t
    character(len=16) :: name = ''
    real(wp) :: rtol = 0      !< both integrators' relative tolerance
    real(wp) :: atol = 0      !< both integrators' absolute tolerance (units of the state)
    !> every value of the report within this relative error of its value
    !> at rtol 1e-12, a felt g's largest and smallest relative to the larger
    !> of the two (the places of the extremes are not bounded: docs/accuracy.md)
    real(wp) :: within = 0
  end type accuracy_preset_t

  type(accuracy_preset_t), parameter :: accuracy_presets(2) = [ &
    ! thesis B.7, the tolerances of every shipped ride (measured worst 1.4e-7,
    ! the half-pipe ride's smallest lateral felt g)
    accuracy_preset_t('reference', 1e-10_wp, 1e-9_wp, 1e-6_wp), &
    ! about half the reference's steps (measured worst 1.6e-5, the drop
    ! ride's lever arm; rtol 1e-7 missed 1e-4 there: 1.2e-4)
    accuracy_preset_t('report', 1e-8_wp, 1e-7_wp, 1e-4_wp)]

contains

  !> The preset called `name`; found = .false. when there is none.
  pure subroutine find_accuracy_preset(name, preset, found)
    character(len=*), intent(in) :: name
    type(accuracy_preset_t), intent(out) :: preset
    logical, intent(out) :: found
    integer :: k
    found = .false.
    do k = 1, size(accuracy_presets)
      if (trim(accuracy_presets(k)%name) == trim(name)) then
        preset = accuracy_presets(k)
        found = .true.
        return
      end if
    end do
  end subroutine find_accuracy_preset
end module design_ride_accuracy
