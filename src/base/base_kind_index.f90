!> The index by name that the registry of kinds keeps beside its kinds
!> (base_kind_registry, for the factories geometry_surface_factory and
!> kinetostatics_force_law_factory): the names in the order registered, the
!> refusal of a name that is empty or taken, the index of a name, and the
!> names as a list for messages.
!>
!> It holds no lock of its own: base_kind_registry reads and changes it only
!> inside its one OpenMP critical section, with the kinds, so that a
!> registration in one thread and a build in another see either all of a
!> kind or none of it.
module base_kind_index
  use base_status, only: status_t, set_status, STATUS_INVALID_INPUT
  implicit none (type, external)
  private
  public :: kind_index_t

  type :: kind_name_t
    character(len=:), allocatable :: name
  end type kind_name_t

  type :: kind_index_t
    private
    type(kind_name_t), allocatable :: names(:)
  contains
    procedure :: add => kind_index_add
    procedure :: find => kind_index_find
    procedure :: listing => kind_index_listing
  end type kind_index_t

contains

  !> Adds `name`; refused if it is empty or taken (`what` names the registry
  !> in the message: 'surface kind', 'force law kind').
  pure subroutine kind_index_add(self, name, what, status)
    class(kind_index_t), intent(inout) :: self
    character(len=*), intent(in) :: name, what
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (len_trim(name) == 0) then
      call set_status(status, STATUS_INVALID_INPUT, what//' '''': a kind needs a name')
    else if (self%find(name) > 0) then
      call set_status(status, STATUS_INVALID_INPUT, what//' '''//name//''' is registered already')
    else
      if (.not. allocated(self%names)) allocate (self%names(0))
      self%names = [self%names, kind_name_t(name)]
    end if
  end subroutine kind_index_add

  !> The index of `name` in the order registered, 0 if unknown.
  pure integer function kind_index_find(self, name) result(k)
    class(kind_index_t), intent(in) :: self
    character(len=*), intent(in) :: name
    if (allocated(self%names)) then
      do k = 1, size(self%names)
        if (self%names(k)%name == name) return
      end do
    end if
    k = 0
  end function kind_index_find

  !> The names quoted, each after a blank: " 'plane' 'ellipsoid'".
  pure function kind_index_listing(self) result(text)
    class(kind_index_t), intent(in) :: self
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    if (.not. allocated(self%names)) return
    do k = 1, size(self%names)
      text = text//' '''//self%names(k)%name//''''
    end do
  end function kind_index_listing
end module base_kind_index
