!> The speed the friction law (4.7) takes where the centreline's curvature
!> rises. Its term H(chi_s) chi_s f3 w^2 alone gives m_w w dw/ds =
!> -f3 chi_s w^2, so over one rise of the curvature by dchi the water keeps
!> the factor exp(-f3 dchi/m_w) of its speed, however fast it goes. On the
!> curves of a body slide (radius a few m) that is a moderate loss; on a
!> tight bend (a 1 m vertical bend: dchi = 1 1/m) the term alone takes
!> about 2/3 of the speed within a few decimetres. The law was identified on
!> the thesis's body slide (table 4.3); such losses are an extrapolation the
!> run reports by place (docs/water.md, "Where the friction law is stretched").
module water_curve_entry
  use base_kinds, only: wp
  use base_text, only: format_with, format_integer
  use water_series, only: water_series_t
  use water_streamline, only: streamline_mass
  implicit none (type, external)
  private
  public :: curve_entry_t, largest_curve_entry, curve_entry_warning_loss, curve_entry_note

  !> A loss of the speed above this fraction is reported as a warning.
  real(wp), parameter :: curve_entry_warning_loss = 0.5_wp

  !> One rise of the curvature between two records of a water run
  type :: curve_entry_t
    real(wp) :: from = 0, to = 0      ! m, arc length of the records where the rise starts and ends
    real(wp) :: rise = 0              ! 1/m, the curvature's rise dchi between them
    real(wp) :: speed_kept = 1        ! exp(-f3 dchi/m_w): the speed the f3 term alone leaves
  end type curve_entry_t

contains

  !> The rise of the recorded curvature with the largest dchi among the first
  !> n records of `s` (runs of records where the curvature grows; resolved
  !> as finely as the records are), with f3 (kg m) and the streamline's mass
  !> m_w (kg). Without any rise: rise = 0, speed_kept = 1.
  pure function largest_curve_entry(s, f3, mass) result(entry)
    type(water_series_t), intent(in) :: s
    real(wp), intent(in) :: f3, mass
    type(curve_entry_t) :: entry
    integer :: i, first
    first = 1
    do i = 2, s%n
      if (s%curvature(i) <= s%curvature(i - 1)) first = i
      if (s%curvature(i) - s%curvature(first) > entry%rise) then
        entry%rise = s%curvature(i) - s%curvature(first)
        entry%from = s%arc_length(first)
        entry%to = s%arc_length(i)
      end if
    end do
    entry%speed_kept = exp(-f3*entry%rise/mass)
  end function largest_curve_entry

  !> A warning when the largest curve entry of the run takes more than
  !> curve_entry_warning_loss of the water's speed (f3 in kg m), else ''.
  function curve_entry_note(s, f3) result(text)
    type(water_series_t), intent(in) :: s
    real(wp), intent(in) :: f3
    character(len=:), allocatable :: text
    type(curve_entry_t) :: entry
    entry = largest_curve_entry(s, f3, streamline_mass)
    text = ''
    if (1 - entry%speed_kept <= curve_entry_warning_loss) return
    text = 'the centreline''s curvature rises by '//format_with(entry%rise, 'f0.3')//' 1/m from arc length '// &
           format_with(entry%from, 'f0.2')//' to '//format_with(entry%to, 'f0.2')//' m: the curve-entry term '// &
           'f3 chi_s w^2 of the friction law (4.7) alone takes '//format_integer(nint(100*(1 - entry%speed_kept)))// &
           ' % of the water''s speed there (factor exp(-f3 dchi/m_w)); (4.7) was identified on the curves '// &
           'of a body slide, so the water past this bend is an extrapolation (docs/water.md)'
  end function curve_entry_note
end module water_curve_entry
