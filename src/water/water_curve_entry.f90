!> The speed the friction law (4.7) takes where the centreline's curvature
!> rises. Its term H(chi_s) chi_s f3 w^2 alone gives m_w w dw/ds =
!> -f3 chi_s w^2, so over one rise of the curvature by dchi the water keeps
!> the factor exp(-f3 dchi/m_w) of its speed, however fast it goes. On the
!> curves of a body slide (radius a few m) that is a moderate loss; on a
!> tight bend (a 1 m vertical bend: dchi = 1 1/m) the term alone takes
!> about 2/3 of the speed within a few decimetres. The law was identified on
!> the thesis's body slide (table 4.3); such losses are an extrapolation the
!> run reports by place (docs/water.md, "Where the friction law is stretched").
!>
!> The thesis explains the term as a splash where the water meets a more
!> curved segment. No splash can take more of the speed than stopping all of
!> the water's motion across the new direction: over a bend that turns the
!> centreline by theta the water keeps at least cos(theta) of its speed.
!> Over a short bend of a small angle (a vertical bend between two slopes:
!> a transition with no constant-curvature part) the term takes far more
!> (bowl.nml at 51 m: 20 % over a 12 deg bend, where a splash could take
!> 2 %): the law is applied where it does not hold, and the run says so by
!> place (splash_bends).
module water_curve_entry
  use base_kinds, only: wp
  use base_text, only: format_with, format_integer
  use water_series, only: water_series_t
  use water_streamline, only: streamline_mass
  implicit none (type, external)
  private
  public :: curve_entry_t, largest_curve_entry, curve_entry_warning_loss, curve_entry_note
  public :: splash_bends, splash_note, splash_report_loss

  !> A loss of the speed above this fraction is reported as a warning.
  real(wp), parameter :: curve_entry_warning_loss = 0.5_wp
  !> Bends where the term takes less than this fraction of the speed are not
  !> reported (rounding and a fitted centreline's ripples stay below it).
  real(wp), parameter :: splash_report_loss = 0.01_wp

  !> One rise of the curvature between two records of a water run
  type :: curve_entry_t
    real(wp) :: from = 0, to = 0      ! m, arc length of the records where the rise starts and ends
    real(wp) :: rise = 0              ! 1/m, the curvature's rise dchi between them
    real(wp) :: speed_kept = 1        ! exp(-f3 dchi/m_w): the speed the f3 term alone leaves
    real(wp) :: turn = 0              ! rad, splash_bends: the turn of the bend beyond the curve before it
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
    text = 'the centreline''s curvature rises by '//fixed(entry%rise, 'f0.3')//' 1/m from arc length '// &
           fixed(entry%from, 'f0.2')//' to '//fixed(entry%to, 'f0.2')//' m: the curve-entry term '// &
           'f3 chi_s w^2 of the friction law (4.7) alone takes '//format_integer(nint(100*(1 - entry%speed_kept)))// &
           ' % of the water''s speed there (factor exp(-f3 dchi/m_w)); (4.7) was identified on the curves '// &
           'of a body slide, so the water past this bend is an extrapolation (docs/water.md)'
  end function curve_entry_note

  !> The bends among the records of `s` where the curve-entry term (f3 in
  !> kg m, the streamline's mass m_w in kg) takes more of the speed than any
  !> splash could and more than splash_report_loss. A bend starts wherever
  !> the recorded curvature starts to grow (at chi_0; a tighter curve inside
  !> a curve starts its own) and ends where it is back at chi_0 or below (or
  !> at the last record); over it the term alone keeps exp(-f3 D/m_w) of the
  !> speed, D the sum of the curvature's rises, while a splash keeps at least
  !> cos(turn), turn = the integral of chi - chi_0 over the arc length
  !> (trapezoids): the centreline's turn beyond the curve it followed before.
  !> A bend is not followed past a turn of 90 deg (no splash bound there) and
  !> one starting inside a bend already reported is not reported again. Each
  !> place: from, to (m), rise = D, speed_kept, turn.
  pure function splash_bends(s, f3, mass) result(places)
    type(water_series_t), intent(in) :: s
    real(wp), intent(in) :: f3, mass
    type(curve_entry_t), allocatable :: places(:)
    real(wp), parameter :: right_angle = acos(-1.0_wp)/2
    type(curve_entry_t) :: bend
    integer :: i, first
    allocate (places(0))
    first = 1
    do while (first < s%n)
      if (.not. s%curvature(first + 1) > s%curvature(first)) then
        first = first + 1
        cycle
      end if
      bend = curve_entry_t(from=s%arc_length(first))
      i = first + 1
      do
        bend%rise = bend%rise + max(s%curvature(i) - s%curvature(i - 1), 0.0_wp)
        bend%turn = bend%turn + (s%arc_length(i) - s%arc_length(i - 1))* &
                    (s%curvature(i) + s%curvature(i - 1) - 2*s%curvature(first))/2
        if (s%curvature(i) <= s%curvature(first) .or. i == s%n .or. bend%turn >= right_angle) exit
        i = i + 1
      end do
      bend%to = s%arc_length(i)
      bend%speed_kept = exp(-f3*bend%rise/mass)
      if (1 - bend%speed_kept > splash_report_loss .and. bend%turn < right_angle .and. &
          bend%speed_kept < cos(bend%turn)) then
        if (size(places) == 0) then
          places = [bend]
        else if (bend%from >= places(size(places))%to) then
          places = [places, bend]
        end if
      end if
      ! on past this rise only: a tighter curve inside the bend starts its own
      first = first + 1
      do while (first < s%n)
        if (.not. s%curvature(first + 1) > s%curvature(first)) exit
        first = first + 1
      end do
    end do
  end function splash_bends

  !> A warning naming every bend of splash_bends (the first five; how many
  !> more), or '' when there is none (f3 in kg m).
  function splash_note(s, f3) result(text)
    type(water_series_t), intent(in) :: s
    real(wp), intent(in) :: f3
    character(len=:), allocatable :: text
    type(curve_entry_t), allocatable :: places(:)
    real(wp), parameter :: degrees = 180/acos(-1.0_wp)
    integer :: k
    places = splash_bends(s, f3, streamline_mass)
    text = ''
    if (size(places) == 0) return
    text = 'the curve-entry term f3 chi_s w^2 of the friction law (4.7) takes more of the water''s speed than a '// &
           'splash could (one that stopped all motion across the new direction keeps cos(turn) of it) at'
    do k = 1, min(size(places), 5)
      associate (b => places(k))
        text = text//trim(merge(' ', ';', k == 1))//' arc length '//fixed(b%from, 'f0.2')//' to '// &
               fixed(b%to, 'f0.2')//' m ('//fixed(100*(1 - b%speed_kept), 'f0.1')//' % in a bend of '// &
               fixed(b%turn*degrees, 'f0.1')//' deg, a splash '//fixed(100*(1 - cos(b%turn)), 'f0.1')// &
               ' %)'
      end associate
    end do
    if (size(places) > 5) text = text//' and '//format_integer(size(places) - 5)//' more bends'
    text = text//': the law does not hold there; past each the water is slower than any splash would leave '// &
           'it (docs/water.md)'
  end function splash_note

  !> x in the edit descriptor `edit` (f0.1, f0.2), a 0 before a bare point.
  pure function fixed(x, edit) result(text)
    real(wp), intent(in) :: x
    character(len=*), intent(in) :: edit
    character(len=:), allocatable :: text
    text = format_with(x, edit)
    if (text(1:1) == '.') text = '0'//text
  end function fixed
end module water_curve_entry
