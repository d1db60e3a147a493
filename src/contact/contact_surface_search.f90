!> Where a contact starts: the point of a surface nearest to a given point
!> (to place the relative chain over surface 1) and the support point of a
!> surface in a direction (where a convex body is extreme, hence touches first).
!>
!> Both search a grid of the parameter box when it is finite (21 x 21 samples;
!> a periodic direction is sampled over one period) and then refine by the
!> foot-point solver's Newton (geometry_foot_point) on the stationarity
!> conditions, with steps clipped to the box. An unbounded direction (a
!> plane) starts from 0, where Newton is exact for the plane. Near a pole of
!> the chart (a ball resting on another a little off-centre: the points
!> near both balls' poles, where r_u vanishes) Newton runs into the box's
!> edge, or stops at the pole, where every u meets the tangency conditions
!> (a ball 1 mm off the top was placed on the top, silently); a surface
!> with other charts is then searched again in the chart regular where the
!> search ended (surface_t chart_toward, chart) and the point taken back to
!> the surface's own (u, v) (chart_parameters).
module contact_surface_search
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_NOT_CONVERGED
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_foot_point, only: foot_point_options_t, foot_point_t, find_foot_point, FOOT_TANGENT, FOOT_SUPPORT, &
    FOOT_STOP_PARAMETER, FOOT_DOMAIN_CLIP, FOOT_STEP_LIMIT, FOOT_SINGULAR
  implicit none (type, external)
  private
  public :: nearest_point, support_point

  integer, parameter :: grid_samples = 21
  real(wp), parameter :: bounded_limit = 1e6_wp   ! a box edge beyond this counts as unbounded
  !> Newton (geometry_foot_point) from the best sample: at most 50 steps,
  !> stopped at a residual or a parameter step of 1e-15 (relative), steps
  !> clipped to the box. A singular Jacobian ends it where it is.
  type(foot_point_options_t), parameter :: search_options = foot_point_options_t( &
    stop_rule=FOOT_STOP_PARAMETER, domain_rule=FOOT_DOMAIN_CLIP, max_steps=50, tolerance=1e-15_wp)

contains

  !> (u, v) where r(u, v) is nearest to p (stationary distance, from the
  !> nearest grid sample): (r - p).r_u = (r - p).r_v = 0.
  subroutine nearest_point(surface, p, u, v, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: p(3)
    real(wp), intent(out) :: u, v
    type(status_t), intent(inout) :: status
    call search(surface, p, .true., u, v, status)
  end subroutine nearest_point

  !> (u, v) where d.r(u, v) is smallest (the point of a convex surface extreme
  !> in the direction -d): d.r_u = d.r_v = 0.
  subroutine support_point(surface, d, u, v, status)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: d(3)
    real(wp), intent(out) :: u, v
    type(status_t), intent(inout) :: status
    call search(surface, d, .false., u, v, status)
  end subroutine support_point

  recursive subroutine search(surface, x, nearest, u, v, status, in_chart)
    class(surface_t), intent(in) :: surface
    real(wp), intent(in) :: x(3)
    logical, intent(in) :: nearest
    real(wp), intent(out) :: u, v
    type(status_t), intent(inout) :: status
    logical, intent(in), optional :: in_chart   ! searching a chart of the surface already (no further chart)
    real(wp) :: box(4), best, value, uu, vv, p(3, 3), u_chart, v_chart, best_r(3)
    type(surface_point_t) :: pt
    type(status_t) :: local
    type(foot_point_options_t) :: options
    type(foot_point_t) :: foot
    class(surface_t), allocatable :: other
    integer :: i, j
    logical :: bounded(2), charted, redo
    u = 0
    v = 0
    best_r = 0
    if (.not. status%ok()) return
    charted = .false.
    if (present(in_chart)) charted = in_chart
    redo = .false.
    call surface%domain(box(1), box(2), box(3), box(4))
    bounded = [max(abs(box(1)), abs(box(2))) < bounded_limit, max(abs(box(3)), abs(box(4))) < bounded_limit]
    if (bounded(1)) u = (box(1) + box(2))/2
    if (bounded(2)) v = (box(3) + box(4))/2
    if (all(bounded)) then
      best = huge(1.0_wp)
      do j = 0, grid_samples - 1
        do i = 0, grid_samples - 1
          uu = box(1) + (box(2) - box(1))*i/real(grid_samples - 1, wp)
          vv = box(3) + (box(4) - box(3))*j/real(grid_samples - 1, wp)
          call surface%evaluate(uu, vv, 0, pt, local)
          if (.not. local%ok()) cycle
          value = objective(pt)
          if (value < best) then
            best = value
            u = uu
            v = vv
            best_r = pt%r
          end if
        end do
      end do
    end if
    options = search_options
    if (nearest) then
      options%equations = FOOT_TANGENT
    else
      options%equations = FOOT_SUPPORT
    end if
    call find_foot_point(surface, x, u, v, options, foot, status)
    if (.not. status%ok()) return
    ! a surface with other charts: a search that runs into the box's edge at
    ! a pole of its chart, or a nearest point that ends at (or beyond) one,
    ! where r_u vanishes and every u meets the tangency conditions (a ball
    ! off-centre on a ball's top was placed at the top), goes on in the chart
    ! regular there (a support point is not so fooled: d.r_v /= 0 at a pole
    ! unless the pole is the answer)
    if (all(bounded) .and. .not. charted .and. surface%has_charts()) redo = foot%reason == FOOT_STEP_LIMIT .or. &
      (nearest .and. (foot%reason == FOOT_SINGULAR .or. surface%chart_margin(v) <= 0))
    if (redo) then
      ! the chart regular where the search ended (else at the best sample): r = P r', a point x = P x', a
      ! direction d.r = (P^T d).r'
      call surface%evaluate(u, v, 0, pt, local)
      if (local%ok()) best_r = pt%r
      call surface%chart(surface%chart_toward(best_r), other, p)
      call search(other, matmul(transpose(p), x), nearest, u_chart, v_chart, status, in_chart=.true.)
      if (status%ok()) call other%evaluate(u_chart, v_chart, 0, pt, status)
      if (status%ok()) call surface%chart_parameters(matmul(p, pt%r), u, v, status)
      return
    end if
    if (foot%reason == FOOT_STEP_LIMIT) then
      if ((bounded(1) .and. (u <= box(1) .or. u >= box(2))) .or. (bounded(2) .and. (v <= box(3) .or. v >= box(4)))) then
        call set_status(status, STATUS_NOT_CONVERGED, 'the '//merge('nearest point', 'support point', nearest)// &
          ' lies beyond the edge of the parameter domain of the '//surface%describe()//' (u, v) in ['// &
          format_short(box(1))//', '//format_short(box(2))//'] x ['//format_short(box(3))//', '// &
          format_short(box(4))//']')
      else
        call set_status(status, STATUS_NOT_CONVERGED, 'no '//merge('nearest point', 'support point', nearest)// &
          ' found on the '//surface%describe())
      end if
    end if
  contains
    real(wp) function objective(q)
      type(surface_point_t), intent(in) :: q
      if (nearest) then
        objective = norm2(q%r - x)
      else
        objective = dot_product(x, q%r)
      end if
    end function objective
  end subroutine search
end module contact_surface_search
