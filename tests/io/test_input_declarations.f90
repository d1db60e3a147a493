!> The declarations of the input variables (io_input_declarations): each
!> (group, name) declared once; every range finite and not empty; every
!> numeric default inside its range and every word default among its words;
!> no text cut by its field; &sweep declares every swept variable and pairs
!> exactly those; and a reader takes its bounds from them (a value outside
!> the declared range is refused with the declared unit) and reports a
!> variable it reads without a declaration as a bug.
program test_input_declarations
  use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
  use base_kinds, only: wp
  use base_status, only: status_t, STATUS_INVALID_INPUT, STATUS_INTERNAL
  use io_declaration, only: declaration_t, VALUE_REAL, VALUE_INTEGER, VALUE_WORDS
  use io_input_declarations, only: declaration, declaration_count, find_declaration, declared_names, &
    declared_unit
  use io_input, only: input_text_t, input_from_text, group_reader_t, open_group
  use design_sweep, only: swept_names
  use io_optimization_config, only: max_points, max_design, max_rides
  use testing, only: check, finish_tests
  implicit none (type, external)

  call each_declared_once()
  call ranges_and_defaults()
  call sweep_shares_its_variables()
  call reader_takes_declared_bounds()
  call finish_tests('test_input_declarations')

contains

  subroutine each_declared_once()
    type(declaration_t) :: d
    integer :: k, i, start
    do k = 1, declaration_count()
      d = declaration(k)
      start = 1
      do i = 1, len_trim(d%groups) + 1
        if (i > len_trim(d%groups) .or. d%groups(i:i) == ' ') then
          if (i > start) call check(find_declaration(d%groups(start:i - 1), d%name) == k, &
                                    '&'//d%groups(start:i - 1)//' '//trim(d%name)//' is declared once')
          start = i + 1
        end if
      end do
      ! a text cut by its field would end in its last character
      call check(len_trim(d%meaning) < len(d%meaning) .and. len_trim(d%meaning) > 0, trim(d%name)//': meaning')
      call check(len_trim(d%choices) < len(d%choices), trim(d%name)//': choices not cut')
      call check(len_trim(d%default) < len(d%default) .and. len_trim(d%default) > 0, trim(d%name)//': default')
      call check(len_trim(d%groups) < len(d%groups) .and. len_trim(d%unit) < len(d%unit) .and. &
                 len_trim(d%shape) < len(d%shape), trim(d%name)//': groups, unit, shape not cut')
    end do
  end subroutine each_declared_once

  subroutine ranges_and_defaults()
    type(declaration_t) :: d
    integer :: k, stat, n, i
    real(wp) :: values(5)
    character(len=:), allocatable :: words
    do k = 1, declaration_count()
      d = declaration(k)
      select case (d%kind)
      case (VALUE_REAL, VALUE_INTEGER)
        call check(ieee_is_finite(d%low) .and. ieee_is_finite(d%high) .and. d%low < d%high, &
                   trim(d%name)//': a finite range, low < high')
        if (d%kind == VALUE_INTEGER) call check(d%low == aint(d%low) .and. d%high == aint(d%high) .and. &
                                                abs(d%high) <= huge(1), trim(d%name)//': whole-number bounds')
        ! a numeric default (one value or a vector) lies in the range
        n = 1 + count([(d%default(i:i) == ',', i=1, len(d%default))])
        read (d%default, *, iostat=stat) values(:min(n, 5))
        if (stat == 0 .and. n <= 5) then
          do i = 1, n
            call check(values(i) <= d%high .and. (values(i) > d%low .or. (.not. d%open_low .and. &
                       values(i) == d%low)), trim(d%name)//': the default '//trim(d%default)//' is allowed')
          end do
        else
          call check(any(trim(d%default) == [character(len=12) :: 'none', 'pi/2', 'pi/2 + 0.3', 'pi/2 - 0.3', &
                                               'table 4.12']), &
                     trim(d%name)//': a default that is no number is one of the known texts')
        end if
      case (VALUE_WORDS)
        if (len_trim(d%choices) > 0 .and. d%default(1:1) == '''') then
          words = ' '//trim(d%choices)//' '
          call check(index(words, ' '//d%default(2:index(d%default(2:), '''')) //' ') > 0, &
                     trim(d%name)//': the default '//trim(d%default)//' is one of the words')
        end if
      end select
    end do
  end subroutine ranges_and_defaults

  !> &sweep varies &rider's and &water's variables: their own declarations
  !> (but mu: in &rider the Coulomb law's parameter, declared with the law;
  !> &sweep's mu is its own).
  subroutine sweep_shares_its_variables()
    type(declaration_t) :: d
    integer :: k
    character(len=:), allocatable :: paired
    do k = 1, size(swept_names)
      call check(find_declaration('sweep', swept_names(k)) > 0, trim(swept_names(k))//' is declared in &sweep')
      call check(find_declaration('sweep', swept_names(k)) == find_declaration('rider', swept_names(k)) .or. &
                 find_declaration('sweep', swept_names(k)) == find_declaration('water', swept_names(k)) .or. &
                 (swept_names(k) == 'mu' .and. find_declaration('rider', 'mu') == 0), &
                 trim(swept_names(k))//': the declaration of &rider or &water')
    end do
    call check(declared_unit('sweep', 'flow_rate') == 'm^3/s' .and. declared_unit('water', 'f1') == 'kg/m', &
               'the units of the shared variables')
    d = declaration(find_declaration('sweep', 'paired'))
    paired = ''
    do k = 1, size(swept_names)
      paired = paired//trim(swept_names(k))//' '
    end do
    call check(trim(d%choices) == trim(paired), '&sweep paired: the swept names, in order')
    call check(size(declared_names('water')) == 20 .and. size(declared_names('solver')) == 9 .and. &
               size(declared_names('water_solver')) == 8, 'the names of &water, &solver and &water_solver '// &
               '(accuracy: &solver only)')
    ! what a fit estimates has the range of the variable it estimates
    do k = 1, declaration_count()
      d = declaration(k)
      if (len_trim(d%range_of) > 0) call check(find_declaration(d%range_of(:index(d%range_of, ' ') - 1), &
        d%range_of(index(d%range_of, ' ') + 1:)) > 0, trim(d%name)//': range_of names a declaration')
    end do
    ! the readers' capacities are the declared largest counts
    block
      type(declaration_t) :: n_points, design_point, n_design, angles
      n_points = declaration(find_declaration('optimize', 'n_points'))
      design_point = declaration(find_declaration('optimize', 'design_point'))
      n_design = declaration(find_declaration('optimize', 'n_design'))
      angles = declaration(find_declaration('optimize', 'start_angles_deg'))
      call check(nint(n_points%high) == max_points .and. nint(design_point%high) == max_points - 1 .and. &
                 nint(n_design%high) == max_design .and. trim(angles%shape) == 'list of at most 50' .and. &
                 max_rides == 50, '&optimize: the capacities of the reader and the declarations agree')
    end block
    call check(same_range('water f1', 'water f2') .and. same_range('water f1', 'water f3') .and. &
               same_range('water f1', 'identify_water twin_f') .and. same_range('sweep mu', 'identify_rider twin_mu'), &
               'f1, f2, f3 and twin_f have one range; twin_mu that of mu')
  end subroutine sweep_shares_its_variables

  logical function same_range(a, b)
    character(len=*), intent(in) :: a, b
    type(declaration_t) :: da, db
    da = declaration(find_declaration(a(:index(a, ' ') - 1), a(index(a, ' ') + 1:)))
    db = declaration(find_declaration(b(:index(b, ' ') - 1), b(index(b, ' ') + 1:)))
    same_range = da%low == db%low .and. da%high == db%high .and. (da%open_low .eqv. db%open_low)
  end function same_range

  subroutine reader_takes_declared_bounds()
    type(input_text_t) :: input
    type(group_reader_t) :: r
    type(status_t) :: status
    real(wp) :: x
    x = 0
    call input_from_text('t.nml', '&water'//new_line('a')//'flow_rate = 2.0, f1 = 0.5 /', input, status)
    call open_group(input, 'water', r, status)
    call check(status%ok(), 'opened &water')
    call r%get('f1', x, status)
    call check(status%ok() .and. x == 0.5_wp, 'f1 read')
    call r%get('flow_rate', x, status)
    call check(status%code == STATUS_INVALID_INPUT .and. index(status%message, 't.nml:2: &water: flow_rate = '// &
               '2.0 is not allowed: must be a finite number in [1.0E-06, 1] (m^3/s)') > 0, &
               'flow_rate outside the declared range: '//status%message)
    status = status_t()
    call r%get('not_declared', x, status)
    call check(status%code == STATUS_INTERNAL, 'a variable read but not declared is a bug')
    status = status_t()
    call open_group(input, 'no_such_group', r, status)
    call check(status%code == STATUS_INTERNAL, 'a group without declarations is a bug')
  end subroutine reader_takes_declared_bounds
end program test_input_declarations
