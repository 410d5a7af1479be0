#pragma once

// The state of the C binding behind phigs.h: the PHIGS system while it is open, the error
// file, the error handler and its mode. Internal to libphigs.

#include "phigs.h"
#include "phigs/Phigs.h"
#include "phigs/core/Error.h"

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

namespace phigs::c {

/// Implementation error numbers of the binding (negative: implementation-defined, ISO 9592).
inline constexpr int kBadArgument = -204;  ///< a NULL pointer or a negative count where data is needed

/// The outputs of the workstation types phigs.h offers (PWST_*): vk's offscreen and PNG
/// targets, the window (when built with GLFW) and the vector hardcopies. Vulkan's settings come
/// from PHIGS_VK_DEVICE and PHIGS_VK_VALIDATION (default lavapipe, validation off; on, every
/// message is printed to stderr).
void registerOutputs(OutputRegistry& registry);

/// The state error function `function` reports while PHIGS is closed: the one for the operating
/// state it requires (2 for (PHOP, *, *, *), 3 WSOP, 5 STOP, 6 STCL, 7 AROP), as ISO 9592 lists it.
int closedStateError(int function);

/// An open system with nothing in it (no workstation, structure or archive open), its error log
/// empty: what an inquiry asked while PHIGS is closed runs on to find the state it requires.
Phigs& closedStateProbe();

/// The ISO name of a function identifier ("OPEN STRUCTURE"), or "function <n>".
std::string functionName(int function);
/// The ISO name of an input function's identifier (Input.cpp), or nullptr.
const char* inputFunctionName(int function);

/// The one PHIGS system of the C binding and its error handling.
class Binding {
public:
    using Handler = void (*)(Pint, Pint, const char*);

    static Binding& instance();

    /// The open system, or nullptr while PHIGS is closed.
    Phigs* system() { return phigs_.get(); }
    /// How many times PHIGS was opened: state kept beside the system (the input session) is
    /// made anew when this moves.
    std::uint64_t openings() const { return openings_; }
    void open(const char* errorFile);
    /// CLOSE PHIGS: the core checks that everything is closed (error 4) before anything goes.
    void close();
    void emergencyClose();

    /// Hands error `number` of `function` to the error handler (when the mode is ON).
    void report(int number, int function);
    /// MESSAGE's line on the error file (stderr without one).
    void message(int workstation, const char* text);
    /// ERROR LOGGING: one line on the error file (or on `file` when it names another file).
    void log(int number, int function, const char* file);
    void setHandler(Handler handler, Handler* old);
    void setMode(Perr_mode mode) { mode_ = mode; }
    Perr_mode mode() const { return mode_; }
    const char* errorFileName() const { return errorFile_.empty() ? nullptr : errorFile_.c_str(); }

    /// The specific workstation type of open workstation `id`: PWST_SPECIFIC_BASE and up, given
    /// at OPEN WORKSTATION and never reused while the library is loaded.
    Pint specificType(Pint id);
    /// The open workstation a specific type names, or nullptr (closed since, or never given).
    Workstation* workstationOfSpecificType(Pint type);
    /// CLOSE WORKSTATION: its specific type names nothing from now on.
    void forgetSpecificType(Pint id) { specificTypes_.erase(id); }

    /// Runs `body` on the open system as function `function`: while PHIGS is closed the state
    /// error the function lists (closedStateError); every error and warning the core raised or
    /// logged goes to the handler, in order.
    template <class Body>
    void call(int function, Body&& body) {
        Phigs* p = system();
        if (!p) {
            report(closedStateError(function), function);
            return;
        }
        const std::size_t before = p->errorLog().size();
        int thrown = 0;
        std::string why;
        try {
            body(*p);
        } catch (const Error& e) {
            thrown = e.number();
            why = e.detail();
        } catch (const std::bad_alloc&) {
            thrown = kOutOfMemory;
        } catch (const std::length_error&) {  // a count past what any container can hold
            thrown = kOutOfMemory;
            why = "a count too large to hold";
        }
        reportSince(function, before, thrown, why);
        showChangesAtOnce(function);
    }

private:
    /// Presents each window workstation whose picture ASAP says is shown but is not (the program
    /// may wait next without calling PHIGS): at once, or while a structure is open (a program
    /// building one, element by element) at most every kBuildingInterval. An error doing so goes
    /// to the handler as `function`'s.
    void showChangesAtOnce(int function);
    static constexpr std::chrono::milliseconds kBuildingInterval{100};
    std::chrono::steady_clock::time_point lastShown_{};
    /// The reason of the error being handed to the handler now (empty: none given).
    std::string reporting_;
    static constexpr int kOutOfMemory = 900;  // ISO 9592: storage overflow has occurred in PHIGS
    void reportSince(int function, std::size_t before, int thrown, const std::string& why);
    /// Hands an error to the handler with its reason, which ERROR LOGGING then writes after the
    /// standard's message.
    void reportWith(int number, int function, const std::string& why);

    std::unique_ptr<Phigs> phigs_;
    std::uint64_t openings_ = 0;
    std::string errorFile_;
    std::FILE* stream_ = nullptr;
    Handler handler_ = perr_hand;
    Perr_mode mode_ = PERR_ON;
    std::map<Pint, Pint> specificTypes_;  // workstation identifier -> its specific type
    Pint nextSpecificType_ = PWST_SPECIFIC_BASE;
};

/// Throws the binding's bad-argument error when `pointer` is NULL (checked after the state).
inline void require(const void* pointer, const char* function) {
    if (!pointer) throw Error(kBadArgument, function, "a required argument is NULL");
}

}  // namespace phigs::c
