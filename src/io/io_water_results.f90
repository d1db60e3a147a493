!> The water's result group: everything of a computed water (water_run)
!> under /water, with its own /water/statistics, so that a file can hold the
!> water, the rider and the evaluation side by side (docs/outputs.md). The
!> file's provenance (root attributes, /input) and the slide's grid
!> (/geometry) belong to the scenario that writes the file.
module io_water_results
  use base_kinds, only: wp
  use base_status, only: status_t
  use water_streamline, only: CORRECTION_FULL, CORRECTION_NO_RADIUS
  use water_flow, only: outcome_name
  use water_run, only: water_description_t, water_result_t, water_inlet_t
  use io_hdf5, only: result_file_t, units_per_second
  implicit none (type, external)
  private
  public :: write_water_results, water_group

  character(len=*), parameter :: water_group = '/water'

contains

  !> Writes the computed water `result` of `description` under /water.
  subroutine write_water_results(file, description, result, status)
    type(result_file_t), intent(inout) :: file
    type(water_description_t), intent(in) :: description
    type(water_result_t), intent(in) :: result
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = water_group//'/', t = water_group//'/table/', st = water_group//'/stations/'
    integer :: n, i
    character(len=16) :: mode
    character(len=:), allocatable :: uu, vu   ! units of u and v of this slide
    real(wp), allocatable :: col(:)   ! a contiguous station column
    logical :: with_inlets

    associate (s => result%series, table => result%table)
      n = s%n
      with_inlets = .false.
      if (allocated(s%inlets)) with_inlets = size(s%inlets) > 0
      call description%slide%parameter_units(uu, vu)
      call file%write_vector(g//'time', s%time(:n), 's', 'time', status)
      call file%write_vector(g//'arc_length', s%arc_length(:n), 'm', &
                             'arc length of the centerline at the water point (from the slide start)', status)
      call file%write_vector(g//'u', s%u(:n), uu, 'surface coordinate u (along the slide)', status)
      call file%write_vector(g//'v', s%v(:n), vu, 'surface coordinate v (across; pi/2 = bottom)', status)
      call file%write_vector(g//'du', s%du(:n), units_per_second(uu), 'rate of u', status)
      call file%write_vector(g//'dv', s%dv(:n), units_per_second(vu), 'rate of v', status)
      call file%write_matrix(g//'position', s%position(:, :n), 'm', 'streamline point (3 x n)', status)
      call file%write_matrix(g//'velocity', s%velocity(:, :n), 'm/s', 'water velocity (3 x n)', status)
      call file%write_vector(g//'speed', s%speed(:n), 'm/s', 'water speed w', status)
      call file%write_vector(g//'height', s%height(:n), 'm', 'water height h (4.24)', status)
      call file%write_vector(g//'width', s%width(:n), 'm', 'water width b (4.19, 4.47)', status)
      call file%write_vector(g//'area', s%area(:n), 'm^2', 'water cross-section area A (F.1, 4.45)', status)
      call file%write_vector(g//'radius', s%radius(:n), 'm', &
                             'equivalent circle radius R (4.15); 0 for non-circular sections', status)
      call file%write_vector(g//'beta', s%beta(:n), 'rad', 'angle between flow and centerline (+ towards +v)', &
                             status)
      call file%write_vector(g//'alpha', s%alpha(:n), 'rad', 'central angle of the water (4.19)', status)
      call file%write_vector(g//'normal_force', s%normal_force(:n), 'N', &
                             'normal force on the 1 kg streamline mass (4.12)', status)
      call file%write_vector(g//'friction_force', s%friction_force(:n), 'N', 'friction F_R (4.7)', status)
      call file%write_vector(g//'curvature', s%curvature(:n), 'm^-1', 'centerline curvature chi (4.8)', status)
      call file%write_vector(g//'froude', s%froude(:n), '1', 'Froude number sqrt(m b w^2/(N A))', status)
      call file%write_vector(g//'kinetic_energy', s%kinetic(:n), 'J', 'kinetic energy of the 1 kg mass', status)
      call file%write_vector(g//'potential_energy', s%potential(:n), 'J', 'potential energy -m g.r', status)
      call file%write_vector(g//'energy', s%kinetic(:n) + s%potential(:n), 'J', 'kinetic + potential energy', &
                             status)
      call file%write_vector(g//'friction_work', s%friction_work(:n), 'J', &
                             'work done by friction since the start (<= 0)', status)
      call file%write_vector(g//'correction_work', s%correction_work(:n), 'J', &
                             'work done by the Saint-Venant term since the start', status)
      ! with inlets: the flow rate along the slide and the inlets (none of
      ! these in a file of one inlet, whose layout stays as it was)
      if (with_inlets) then
        call file%write_vector(g//'flow_rate', s%flow(:n), 'm^3/s', &
                               'flow rate Q at the sample: the start''s and the inlets'' joined upstream', status)
        call write_inlets(file, s%inlets, status)
      end if
      ! the edges at the samples only where they were solved there (edges = .true.)
      if (s%edges) then
        call file%write_vector(g//'left_edge_u', s%left_edge(1, :n), uu, &
                               'u of the left water edge, towards +v (4.25)', status)
        call file%write_vector(g//'left_edge_v', s%left_edge(2, :n), vu, 'v of the left water edge (4.25)', status)
        call file%write_vector(g//'right_edge_u', s%right_edge(1, :n), uu, 'u of the right water edge (4.26)', &
                               status)
        call file%write_vector(g//'right_edge_v', s%right_edge(2, :n), vu, 'v of the right water edge (4.26)', &
                               status)
        call file%write_matrix(g//'left_point', s%left_point(:, :n), 'm', 'left water edge point (3 x n)', status)
        call file%write_matrix(g//'right_point', s%right_point(:, :n), 'm', 'right water edge point (3 x n)', &
                               status)
        call file%write_integers(g//'edge_solved', s%edge_solved(:n), '1', &
                                 '1: edges solved (4.25-4.26); 0: circle estimate (an edge beyond the slide''s '// &
                                 'end, or a failed solve)', status)
      end if
      call file%set_attribute(water_group, 'outcome', outcome_name(s%outcome), status)
      call file%set_attribute(water_group, 'flow_rate_m3_per_s', s%flow_rate, status)
      mode = 'off'
      if (description%correction == CORRECTION_FULL) mode = 'full'
      if (description%correction == CORRECTION_NO_RADIUS) mode = 'no_radius'
      call file%set_attribute(water_group, 'correction', trim(mode), status)
      call file%set_attribute(water_group, 'friction_f1_f2_f3', [description%f1, description%f2, description%f3], &
                              status)
      call file%set_attribute(water_group, 'time_bound_s', s%time_bound, status)
      call file%set_attribute(water_group, 'edges_at_samples', merge(1, 0, s%edges), status)

      ! no table when the run stopped before its field and table were built
      if (allocated(table%arc_length)) then
        call file%write_vector(t//'arc_length', table%arc_length, 'm', 'centerline arc length', status)
        call file%write_vector(t//'u', table%u, uu, 'u at that arc length', status)
        call file%write_vector(t//'time', table%time, 's', 'time the water point passes', status)
        call file%write_vector(t//'v', table%v, vu, 'v of the water middle', status)
        call file%write_vector(t//'speed', table%speed, 'm/s', 'water speed', status)
        call file%write_vector(t//'height', table%height, 'm', 'water height', status)
        call file%write_vector(t//'width', table%width, 'm', 'water width', status)
        call file%write_vector(t//'beta', table%beta, 'rad', 'flow angle to the centerline', status)
        call file%write_vector(t//'v_left', table%v_left, vu, 'v of the left edge', status)
        call file%write_vector(t//'v_right', table%v_right, vu, 'v of the right edge', status)
        if (with_inlets) call file%write_vector(t//'flow_rate', table%flow_rate, 'm^3/s', &
                                                       'flow rate Q (the inlets upstream added)', status)
        call file%write_integers(t//'edge_solved', table%edge_solved, '1', &
                                 '1: edges solved (4.25-4.26) at the row or interpolated between solved samples; '// &
                                 '0: circle estimate (an edge beyond the slide''s end)', status)
        if (size(table%arc_length) > 0) then
          call file%make_scale(t//'arc_length', status)
          call file%attach_scale(t//'arc_length', t, status)
        end if
      end if

      if (size(s%stations) > 0) then
        call file%write_vector(st//'arc_length', description%stations, 'm', 'station arc length (input)', status)
        col = s%stations%u
        call file%write_vector(st//'u', col, uu, 'u of the station', status)
        col = s%stations%time
        call file%write_vector(st//'time', col, 's', 'time the water passes', status)
        col = s%stations%v
        call file%write_vector(st//'v', col, vu, 'v of the streamline', status)
        col = s%stations%v_middle
        call file%write_vector(st//'v_middle', col, vu, &
                               'v of the middle between the edges (as measured, 4.32)', status)
        col = s%stations%v_left
        call file%write_vector(st//'v_left', col, vu, 'v of the left edge', status)
        col = s%stations%v_right
        call file%write_vector(st//'v_right', col, vu, 'v of the right edge', status)
        col = s%stations%speed
        call file%write_vector(st//'speed', col, 'm/s', 'water speed', status)
        col = s%stations%height
        call file%write_vector(st//'height', col, 'm', 'water height', status)
        col = s%stations%width
        call file%write_vector(st//'width', col, 'm', 'water width', status)
        call file%write_integers(st//'reached', [(merge(1, 0, s%stations(i)%reached), i = 1, size(s%stations))], &
                                 '1', '1 if the water reached the station', status)
        call file%make_scale(st//'arc_length', status)
        call file%attach_scale(st//'arc_length', st, status)
      end if

      call file%write_count(g//'statistics/steps', int(s%stats%steps), '1', 'integrator steps', status)
      call file%write_count(g//'statistics/rhs_evaluations', int(s%stats%rhs_evaluations), '1', &
                            'right-hand-side evaluations', status)
      call file%write_count(g//'statistics/root_evaluations', int(s%stats%root_evaluations), '1', &
                            'root-function evaluations', status)
      call file%write_count(g//'statistics/error_test_failures', int(s%stats%error_test_failures), '1', &
                            'error test failures', status)
      call file%write_scalar(g//'statistics/cpu_time', result%cpu, 's', &
                             'process CPU time of the water computation (run, field, table)', status)
      if (n > 0) then
        call file%make_scale(g//'time', status)
        call file%attach_scale(g//'time', water_group, status)
        call file%attach_components(water_group, status)
      end if
    end associate
  end subroutine write_water_results
  !> /water/inlets: each inlet as given and whether and when it joined.
  subroutine write_inlets(file, inlets, status)
    type(result_file_t), intent(inout) :: file
    type(water_inlet_t), intent(in) :: inlets(:)
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: g = water_group//'/inlets/'
    integer :: i
    call file%write_vector(g//'arc_length', inlets%arc_length, 'm', &
                           'centerline arc length where the inlet''s water joins (input)', status)
    call file%write_vector(g//'flow_rate', inlets%flow_rate, 'm^3/s', 'flow rate the inlet adds (input)', status)
    call file%write_vector(g//'speed', inlets%speed, 'm/s', 'speed of the inlet''s water along the surface (input)', &
                           status)
    call file%write_vector(g//'beta', inlets%beta, 'rad', &
                           'angle of the inlet''s water to the centerline, + towards +v (input)', status)
    call file%write_integers(g//'joined', [(merge(1, 0, inlets(i)%joined), i = 1, size(inlets))], '1', &
                             '1 if the water reached the inlet and took its water', status)
    call file%write_vector(g//'time', merge(inlets%time, 0.0_wp, inlets%joined), 's', &
                           'time the water passed the inlet (0 where it did not reach it)', status)
    call file%make_scale(g//'arc_length', status)
    call file%attach_scale(g//'arc_length', g, status)
  end subroutine write_inlets
end module io_water_results
