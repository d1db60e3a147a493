!> The water over centerline arc length: one row every `step` metres from
!> the start, read from the water field (cubic Hermite between the run's
!> samples, water_field), the edges included: v_left and v_right of a row are
!> the edge curves at the row's cross-section u (where the water's edges cross
!> that section), as the field gives them to other models.
!> The edge curves come from edge points solved (4.25-4.26) either at every
!> sample of the run (`edges = .true.`) or, for a run that kept no edges
!> (`edges = .false.`), at the water point of every row (solve_row_edges):
!> the table's step, not the output step, then sets the cost. Where a row's
!> section lies outside an edge curve's range (an edge beyond the slide's end)
!> the circle estimate v -+ (b/2)/|r_v| stands there, flagged edge_solved = 0.
module water_table
  use base_kinds, only: wp
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_point_t
  use water_streamline, only: streamline_t, water_point_t, water_point, water_rates_t, water_point_rates
  use water_boundaries, only: water_edges
  use water_field, only: water_field_t, water_at_t, WATER_INSIDE
  implicit none (type, external)
  private
  public :: water_table_t, new_water_table, solve_row_edges

  type :: water_table_t
    real(wp), allocatable :: arc_length(:), u(:), time(:), v(:), speed(:), height(:), width(:), &
      beta(:), v_left(:), v_right(:)
    real(wp), allocatable :: flow_rate(:)    ! m^3/s (the inlets upstream added)
    integer, allocatable :: edge_solved(:)   ! 1: edges from (4.25-4.26); 0: circle estimate
  end type water_table_t

contains

  !> The arc lengths of the rows: from the field's first sample every `step`.
  subroutine row_arc_lengths(field, step, s, status)
    type(water_field_t), intent(in) :: field
    real(wp), intent(in) :: step
    real(wp), allocatable, intent(out) :: s(:)
    type(status_t), intent(inout) :: status
    real(wp) :: s0, s1
    integer :: m, j
    call field%arc_length_range(s0, s1)
    m = 0
    if (field%node_count() >= 2) then
      if (.not. step > 0) then
        call set_status(status, STATUS_INVALID_INPUT, 'water table: the step must be > 0')
        return
      end if
      m = int((s1 - s0)/step) + 1
    end if
    s = [(min(s0 + (j - 1)*step, s1), j = 1, m)]
  end subroutine row_arc_lengths

  !> The edge points (u, v, du/dt, dv/dt) of the water point at every row,
  !> Newton warm-started from the previous row's offsets; rows where no foot
  !> exists are left out.
  subroutine solve_row_edges(field, model, step, left_rows, right_rows, status)
    type(water_field_t), intent(in) :: field
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: step
    real(wp), allocatable, intent(out) :: left_rows(:, :), right_rows(:, :)
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: s(:)
    type(water_at_t) :: w
    type(water_point_t) :: q
    type(water_rates_t) :: rates
    type(status_t) :: st
    real(wp) :: y(7), l(2), r(2), pl(3), pr(3), l_rate(2), r_rate(2), prev_l(2), prev_r(2)
    integer :: j, k
    logical :: warm
    call row_arc_lengths(field, step, s, status)
    if (.not. status%ok()) return
    allocate (left_rows(4, size(s)), right_rows(4, size(s)))
    k = 0
    warm = .false.
    do j = 1, size(s)
      call field%at_arc_length(s(j), w)
      if (w%location /= WATER_INSIDE) cycle
      y = [w%u, w%v, w%du_dt, w%dv_dt, w%height, 0.0_wp, 0.0_wp]
      st%code = 0
      call water_point(model, y, q, st)
      if (st%ok()) call water_point_rates(model, y, q, rates, st)
      if (st%ok()) then
        if (warm) then
          call water_edges(model%channel, q, l, r, pl, pr, st, prev_l + [w%u, w%v], prev_r + [w%u, w%v], &
                           rates=rates, left_rate=l_rate, right_rate=r_rate)
        else
          call water_edges(model%channel, q, l, r, pl, pr, st, rates=rates, left_rate=l_rate, right_rate=r_rate)
        end if
      end if
      warm = st%ok()
      if (.not. st%ok()) cycle
      k = k + 1
      left_rows(:, k) = [l, l_rate]
      right_rows(:, k) = [r, r_rate]
      prev_l = l - [w%u, w%v]; prev_r = r - [w%u, w%v]   ! offsets from the water point
    end do
    left_rows = left_rows(:, :k)
    right_rows = right_rows(:, :k)
  end subroutine solve_row_edges

  !> The table of a run (its field `field`, its model `model`) every `step` m.
  subroutine new_water_table(field, model, step, table, status)
    type(water_field_t), intent(in) :: field
    type(streamline_t), intent(in) :: model
    real(wp), intent(in) :: step
    type(water_table_t), intent(out) :: table
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: s(:)
    type(water_at_t) :: w
    type(surface_point_t) :: p
    type(status_t) :: st
    real(wp) :: half
    integer :: m, j
    call row_arc_lengths(field, step, s, status)
    if (.not. status%ok()) return
    m = size(s)
    allocate (table%u(m), table%time(m), table%v(m), table%speed(m), table%height(m), &
              table%width(m), table%beta(m), table%v_left(m), table%v_right(m), table%edge_solved(m), &
              table%flow_rate(m))
    table%arc_length = s
    do j = 1, m
      call field%at_arc_length(s(j), w)
      table%u(j) = w%u; table%time(j) = w%time; table%v(j) = w%v; table%speed(j) = w%speed
      table%height(j) = w%height; table%width(j) = w%width; table%beta(j) = w%beta
      table%flow_rate(j) = w%flow_rate
      if (w%edges%left_location == WATER_INSIDE .and. w%edges%right_location == WATER_INSIDE) then
        table%v_left(j) = w%edges%v_left; table%v_right(j) = w%edges%v_right
        table%edge_solved(j) = 1
      else
        half = 0
        call model%channel%evaluate(w%u, w%v, 1, p, st)
        if (st%ok()) half = 0.5_wp*w%width/norm2(p%rv)
        table%v_left(j) = w%v + half; table%v_right(j) = w%v - half
        table%edge_solved(j) = 0
      end if
    end do
  end subroutine new_water_table
end module water_table
