!> &solver: the ODE integrator's settings and the simulated time span; a
!> ride's accuracy preset (both integrators' tolerances, design_ride_accuracy);
!> and the bound on the number of stored outputs (memory) every scenario
!> checks before it starts.
module io_solver_config
  use base_kinds, only: wp
  use base_text, only: format_integer, format_short
  use base_status, only: status_t, set_status, STATUS_INTERNAL
  use base_series, only: max_series_bytes
  use numerics_ode, only: ode_options_t, ODE_ADAMS, ODE_BDF
  use design_ride_accuracy, only: accuracy_preset_t, find_accuracy_preset
  use io_input, only: input_text_t, group_reader_t, open_group, format_real, invalid
  implicit none (type, external)
  private
  public :: solver_config_t, read_solver_config, apply_accuracy, check_output_count, max_result_bytes, max_outputs

  !> Most memory the stored time series of one run may take (refused above).
  real(wp), parameter :: max_result_bytes = max_series_bytes
  !> Most output times of one run.
  real(wp), parameter :: max_outputs = 1e7_wp

  type :: solver_config_t
    type(ode_options_t) :: options
    real(wp) :: duration = 10           !< s
    logical :: duration_given = .false. !< &solver duration was given (water: else up to the slide's end)
    real(wp) :: output_step = 0.01_wp   !< s
    !> &solver accuracy: 'tolerances' (rtol and atol as given) or a preset
    !> of a ride's two integrators (apply_accuracy)
    character(len=16) :: accuracy = 'tolerances'
    logical :: accuracy_given = .false. !< &solver accuracy was given (else the scenario's default)
  end type solver_config_t

contains

  !> &solver, or the same variables in the group `group` (the ride's
  !> &water_solver); values not given keep `defaults` (or the type's).
  !> `presets`: the scenario rides (ride, sweep) and takes &solver accuracy
  !> (then apply_accuracy); elsewhere a preset is refused, as its guarantee
  !> is measured on the ride report only.
  subroutine read_solver_config(input, config, status, group, defaults, presets)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(out) :: config
    type(status_t), intent(inout) :: status
    character(len=*), intent(in), optional :: group
    type(solver_config_t), intent(in), optional :: defaults
    logical, intent(in), optional :: presets
    character(len=8) :: method
    type(group_reader_t) :: r
    logical :: takes_presets

    if (present(defaults)) config = defaults
    method = merge('bdf  ', 'adams', config%options%method == ODE_BDF)
    if (present(group)) then
      call open_group(input, group, r, status)
    else
      call open_group(input, 'solver', r, status)
    end if
    call r%get('method', method, status)
    call r%get('rtol', config%options%rtol, status)
    call r%get('atol', config%options%atol, status)
    call r%get('max_steps', config%options%max_steps, status)
    call r%get('initial_step', config%options%initial_step, status)
    call r%get('max_step', config%options%max_step, status)
    call r%get('duration', config%duration, status)
    call r%get('output_step', config%output_step, status)
    if (r%group == 'solver') then
      call r%get('accuracy', config%accuracy, status)
      takes_presets = .false.
      if (present(presets)) takes_presets = presets
      if (.not. takes_presets) &
        call r%refuse_given(['accuracy'], 'only the ride and the sweep take an accuracy preset (its '// &
                            'guarantee is measured on the ride report, docs/accuracy.md): give rtol and atol', status)
    end if
    if (.not. status%ok()) return
    config%duration_given = r%has('duration')
    config%accuracy_given = r%group == 'solver' .and. r%has('accuracy')
    if (config%output_step > config%duration .and. config%duration_given) then
      call r%invalid('output_step', format_real(config%output_step), &
                     'must not exceed duration = '//format_real(config%duration)//' s', status)
      return
    end if
    config%options%method = merge(ODE_BDF, ODE_ADAMS, method == 'bdf')
  end subroutine read_solver_config

  !> &solver accuracy: a preset sets rtol and atol of both a ride's
  !> integrators, the rider's (`solver`) and the water's (`water`, read from
  !> &water_solver); 'tolerances' leaves them as given. A preset given with
  !> a tolerance given is refused (one would silently win); a scenario's
  !> default preset (the sweep's 'report', accuracy not given) yields to a
  !> tolerance given: the input's tolerances are used, as they were before
  !> the sweep had a default preset.
  subroutine apply_accuracy(input, solver, water, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(inout) :: solver
    type(ode_options_t), intent(inout) :: water
    type(status_t), intent(inout) :: status
    character(len=*), parameter :: groups(2) = [character(len=12) :: 'solver', 'water_solver']
    type(accuracy_preset_t) :: preset
    type(group_reader_t) :: r
    logical :: found
    integer :: k
    if (.not. status%ok() .or. solver%accuracy == 'tolerances') return
    if (.not. solver%accuracy_given) then
      do k = 1, size(groups)
        call open_group(input, trim(groups(k)), r, status)
        if (r%has('rtol') .or. r%has('atol')) solver%accuracy = 'tolerances'
      end do
      if (.not. status%ok() .or. solver%accuracy == 'tolerances') return
    end if
    do k = 1, size(groups)
      call open_group(input, trim(groups(k)), r, status)
      call r%refuse_given(['rtol', 'atol'], 'not with &solver accuracy = '''//trim(solver%accuracy)// &
                          ''', which sets rtol and atol of both &solver and &water_solver: give either the '// &
                          'preset or the tolerances', status)
    end do
    if (.not. status%ok()) return
    call find_accuracy_preset(solver%accuracy, preset, found)
    if (.not. found) then
      call set_status(status, STATUS_INTERNAL, '&solver accuracy = '''//trim(solver%accuracy)//''' is '// &
                      'declared but design_ride_accuracy has no such preset (a bug)')
      return
    end if
    solver%options%rtol = preset%rtol
    solver%options%atol = preset%atol
    water%rtol = preset%rtol
    water%atol = preset%atol
  end subroutine apply_accuracy

  !> The outputs a run over `duration` stores, `values_per_output` numbers
  !> each, must stay within max_outputs and max_result_bytes; the message
  !> names duration and output_step. `what` names the run ('point_mass').
  subroutine check_output_count(input, config, duration, values_per_output, what, status)
    type(input_text_t), intent(in) :: input
    type(solver_config_t), intent(in) :: config
    real(wp), intent(in) :: duration
    integer, intent(in) :: values_per_output
    character(len=*), intent(in) :: what
    type(status_t), intent(inout) :: status
    real(wp) :: outputs, bytes
    if (.not. status%ok()) return
    outputs = duration/config%output_step + 2
    bytes = outputs*values_per_output*8
    if (outputs <= max_outputs .and. bytes <= max_result_bytes) return
    call invalid(input, 'solver', 'output_step', format_real(config%output_step), 'with duration = '// &
                   format_real(duration)//' s the '//what//' run would store '//format_short(outputs)// &
                   ' outputs ('//format_short(bytes/1024**3)//' GB); at most '// &
                   format_integer(nint(max_outputs))//' outputs and '// &
                   format_short(max_result_bytes/1024**3)//' GB: raise output_step or shorten duration', status)
  end subroutine check_output_count
end module io_solver_config
