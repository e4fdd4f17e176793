# cmake -DCOMMAND="prog|arg|..." -DEXPECT=regex [-DTIMEOUT=s] -P expect_abort.cmake
# Passes when COMMAND exits non-zero and its output (stdout + stderr) matches EXPECT.
string(REPLACE "|" ";" command "${COMMAND}")
if(NOT TIMEOUT)
  set(TIMEOUT 50)
endif()
execute_process(COMMAND ${command}
                RESULT_VARIABLE status
                OUTPUT_VARIABLE output
                ERROR_VARIABLE output
                TIMEOUT ${TIMEOUT})
message("${output}")
if(status EQUAL 0)
  message(FATAL_ERROR "expected a non-zero exit status, got 0")
endif()
if(NOT output MATCHES "${EXPECT}")
  message(FATAL_ERROR "exit status ${status} but the output lacks \"${EXPECT}\"")
endif()
message("exit status ${status} and \"${EXPECT}\" found, as expected")
