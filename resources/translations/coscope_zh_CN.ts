<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>CoreText</name>
    <message>
        <source>Not ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready to switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switched on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>voltage enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>quick stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>switch on disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manufacturer specific (bit 8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>remote</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>target reached</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>internal limit active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation mode specific (bit 12)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>operation mode specific (bit 13)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manufacturer specific (bit 14)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>manufacturer specific (bit 15)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shutdown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on + enable operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable voltage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on / disable operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile position (PP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity (VL)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile velocity (PV)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile torque (PT)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing (HM)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interpolated position (IP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic synchronous position (CSP)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic synchronous velocity (CSV)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cyclic synchronous torque (CST)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vl</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pv</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>csp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>csv</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cst</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter pre-operational</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset communication</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operational</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pre-operational</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toggle bit not alternated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO protocol timed out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Client/server command specifier not valid or unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid block size (block mode only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid sequence number (block mode only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CRC error (block mode only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Out of memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsupported access to an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attempt to read a write-only object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Attempt to write a read-only object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object does not exist in the object dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object cannot be mapped to the PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The number and length of the objects to be mapped would exceed the PDO length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General parameter incompatibility reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General internal incompatibility in the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Access failed due to a hardware error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter does not match</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too high</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too low</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sub-index does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Invalid value for parameter (download only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value of parameter written too high (download only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value of parameter written too low (download only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maximum value is less than minimum value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resource not available: SDO connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>General error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of local control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of the present device state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object dictionary dynamic generation fails or no object dictionary is present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No data available</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>opening</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Ds402FaultText</name>
    <message>
        <source>Error code (603Fh) %1h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — vendor alarm </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>alarm number 0x%1 (not in the %2 table)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Ds402StateDiagram</name>
    <message>
        <source>13 any fault</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Ds402VendorNotes</name>
    <message>
        <source>P1-01 must be 0x0C (standard CANopen mode) or the drive ignores the controlword. Do not send NMT Reset Node while the servo is on: the drive raises AL401.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>H02-00 must be 8 (CANopen control) or the drive ignores the controlword.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The DEXMART DEV has no CiA 402 state machine: its two motors are run through the Multi-Drive objects (3051h/3052h). Use the Object dictionary dock for it.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>EventLog</name>
    <message>
        <source>EMCY reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO abort</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dropped frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Info</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat back after timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No heartbeat for %1 ms (period %2 ms)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message>
        <source>NMT (short frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT frame must carry 2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT node control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command specifier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 (all)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node guarding request to node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node guarding request (RTR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT error control (empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error control frame without state byte</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boot-up node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat node %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat / guarding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toggle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMCY node %1: error reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, reg %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMCY frame shorter than 8 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Emergency</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error register (1001h)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Manufacturer-specific</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, %1 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO request (client → server)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO response (server → client)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sub-index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Segment data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error frame, class %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TIME stamp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LSS command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(29-bit identifier, not CANopen)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 node %2, %3 bytes</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LogLoadJob</name>
    <message>
        <source>Opening %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot open</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LogSaveJob</name>
    <message>
        <source>Saving %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unknown log format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot write format &apos;%2&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>OdTreeModel</name>
    <message>
        <source>sub %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, PDO-mappable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Limits: %1 … %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
Differs from the default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1 %2: %3 (bytes %4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PdoDbcExport</name>
    <message>
        <source>%1: cannot write the DBC file (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO layout exported to %1: %2 PDO messages, %3 raw signals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PDO layout as DBC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DBC file (*.dbc)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PdoVendorNotes</name>
    <message>
        <source>Delta ASDA-A2: the drive speaks standard CANopen only when P1-01 (2101h) = 0x0C; check it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delta writes every P-parameter (2000h–2FFFh) to EEPROM on each SDO write; P-parameters written by PDO are stored only when P3-11 X = 1 (wears the EEPROM).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. Two PDOs with the same COB-ID within 1 ms raise alarm AL112.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RPDOs with a transmission type 0–240 act at the next SYNC: the master must send SYNC every cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AIMOTOR: CiA 402 objects act only when H02-00 (2002h:01) = 8 (CANopen control).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AIMOTOR&apos;s default PDOs are synchronous (type 1): they are sent or applied only when a SYNC arrives. Start a SYNC producer, or choose an event-driven type.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only CiA 402 objects (6000h–6FFFh) can be mapped; at most 8 objects per PDO.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DEXMART DEV: the COB-ID is read-only, so a PDO cannot be switched off while it is remapped: the mapping changes while the message is in use.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. The power-on mapping comes from parameter 09-26; a change made here is lost at power-off unless stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Two motors: the M1/M2 values live in the Multi-Drive objects (3046h status, 3051h commands).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No dictionary is known for this node: objects cannot be offered by name. Scan the node (Nodes dock) or assign a dictionary first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive did not answer in time. Check that it is powered, that its node-ID is right, and the cable, termination and bit rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive does not allow this object in a PDO. Take another object, or check the manual&apos;s &quot;PDO&quot; column for it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too much data for one PDO on this drive: use fewer objects or smaller ones (at most 64 bits; some drives allow at most 8 objects).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive reports a general parameter incompatibility: check that the PDO number exists and the values fit together.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This parameter is read-only on this drive (some drives fix the COB-ID). Keep the current value.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive does not have this object: this PDO number may not exist on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive refused the value: check the allowed range (transmission type, inhibit time, event timer).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive does not accept this in its present state. It must be pre-operational (the wizard sends that first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Look up abort code 0x%1 in the drive&apos;s manual.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The values read back differ from those written: the drive may have adjusted or ignored one. Read the PDO again and compare.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent at the next SYNC after a value changed (synchronous acyclic, type 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent on every SYNC (synchronous cyclic, type 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent once every %1 SYNCs (synchronous cyclic, type %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sampled at SYNC, sent only when asked for (RTR-only synchronous, type 252)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent only when asked for (RTR-only event-driven, type 253)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent when a value changes and/or every event-timer period (event-driven, type %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied as soon as it arrives (event-driven, type %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reserved transmission type %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Decoding the PDOs with the assigned dictionaries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault reset (transition 15): clears the fault once its cause is removed. Sends controlword 6040h = 0000h, then 0080h (bit 7 rising). Expect Switch on disabled: fault bit 3 off, bit 6 on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shutdown (transition 2): gets the drive ready, the motor stays without power. Sends 6040h = 0006h. Expect Ready to switch on: bits 0 and 5 on, bit 6 off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on (transition 3): switches the power stage on, the motor is not yet energised; needs main power. Sends 6040h = 0007h. Expect Switched on: bits 0, 1, 4 (voltage enabled) and 5 on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable operation (transition 4): energises the motor, which then holds its position and follows commands. Sends 6040h = 000Fh. Expect Operation enabled: bits 0, 1, 2 and 5 on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>booting (boot-up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running (operational)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready (pre-operational)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>seen</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>TraceFilter</name>
    <message>
        <source>filter: &apos;%1&apos; is not a node-ID (0-127)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>filter: &apos;node:&apos; needs node-IDs, e.g. node:5,6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>filter: unknown service &apos;%1&apos; (NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ SDO_RESP NMT_EC LSS_REQ LSS_RESP, or sdo, pdo)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>filter: &apos;svc:&apos; needs service names, e.g. svc:sdo,emcy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>filter: &apos;%1&apos; is not a COB-ID or range in hex (e.g. 580-5FF)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>filter: &apos;id:&apos; needs COB-IDs in hex, e.g. id:580-5FF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Grouping SDO transfers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filtering</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>WizardFramesPane</name>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dir</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>WizardMenu</name>
    <message>
        <source>Baud rate and node-ID…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CiA 402 enable step-through…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO mapping…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::BusStatusBar</name>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restart controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller went bus-off and sends nothing; restart it (check wiring, termination and bit rate first)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · listen-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 frames/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>load %1 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Estimated from frame lengths with worst-case bit stuffing at %1 bit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dropped %L1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>errors %L1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error passive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bus-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · TEC %1 REC %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN controller state from the last error frame (transmit / receive error counters)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller restarted after bus-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Restart after bus-off failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last restart failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConnectDialog</name>
    <message>
        <source>Connect to a CAN bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(recent connections)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recent:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Virtual drives (sim://)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>socketcand server (remote CAN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Qt CAN plugin: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Replay a log file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Backend:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No CAN interfaces found. A virtual one for trying: &lt;tt&gt;sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up&lt;/tt&gt;. A real adapter: &lt;tt&gt;sudo ip link set can0 up type can bitrate 500000&lt;/tt&gt;. Then choose the backend again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Port:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Virtual drives on the in-process bus:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive (dictionary)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log to replay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>10×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>100×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(adapter setting)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN FD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>data %L1 Mbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only (never transmit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type or paste a bus URL, e.g. socketcan://can0?bitrate=500000</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>URL:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listed by the plugin without finding an adapter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not bring the interface up: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is up (virtual CAN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is up at %L2 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, CAN FD data %L1 Mbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, controller in error warning (TEC %1, REC %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, controller error passive (TEC %1, REC %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, controller is bus-off: check wiring, termination and bit rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, controller stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unverified: the %1 plugin lists %2 without finding an adapter; connecting shows whether one is there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To change its bit rate, run:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring it up with:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change bit rate now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bring up now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CoScope runs without the right to configure network interfaces: run the command above in a terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose at least one virtual drive</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConsoleDock</name>
    <message>
        <source>Console</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::DcfApplyDialog</name>
    <message>
        <source>Apply DCF to node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to write: every value of %1 is already on node %2 or cannot be written (%3 entries, listed below).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write %1 object(s) from &lt;b&gt;%2&lt;/b&gt; to &lt;b&gt;node %3&lt;/b&gt; over SDO? Each write is sent once; a refused write is reported and the others continue. %4 entries are not written (greyed).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node now / result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write %1 object(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1: %2 of %3 write(s) done, %4 refused%5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, cancelled before the rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402FramesTabs</name>
    <message>
        <source>Frames (requests and responses)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dry run (what will be sent)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402ModeBox</name>
    <message>
        <source>Mode of operation (6060h / 6061h)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set and verify</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1 ✓</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402MotionPlot</name>
    <message>
        <source>position 6064h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>position 6064h: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity 606Ch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity 606Ch: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The test move&apos;s motion shows here</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StateDiagram</name>
    <message>
        <source>State not read yet</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StatusPanel</name>
    <message>
        <source>Statusword (6041h): not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Statusword (6041h) = %1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StepBar</name>
    <message>
        <source>Step through — one button per transition</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1  Fault reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2  Shutdown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3  Switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>4  Enable operation…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive is enabled (Operation enabled). Choose a mode and try a test move, or press Disable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop is active: press Disable to leave it (Disable voltage, transition 12).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive is in %1; wait for it to settle, then read the state again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402TestMoveBox</name>
    <message>
        <source>Test move (optional, small limits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jog (profile velocity, 60FFh)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Short move (profile position, 607Ah relative)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time limit:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm test move…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold to run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The motor moves only while this button is held down; releasing it stops the motor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>turn at %1 (profile velocity, 60FFh = %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>move %1 at up to %2 (profile position, relative: 607Ah = %3, 6081h = %4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402Wizard</name>
    <message>
        <source>CiA 402 enable step-through</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection lost (bus %1). The drive was told to disable if the bus still accepted it; otherwise its own communication-loss reaction (6007h) applies. Check the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection changed. Choose the drive again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>application quits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only connection: this wizard is disabled because it would have to send (SDO to 6040h/6041h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wizard destroyed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive state (CiA 402 state machine)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Statusword bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1; replay it with: coscope-cli script run BUS %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Brakes on the drive&apos;s quick stop ramp (6040h = 0002h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Removes power from the motor: Shutdown then Disable voltage (6040h = 0006h, 0000h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dry run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the exact SDO sequence of the enable, without sending anything.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to a bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only connection: the wizard does not send.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive chosen.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 is not being read: press “Read state” to read it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 is not a CiA 402 drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wizard closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check main power, the enable and safe torque off (STO) inputs, and the drive&apos;s own display.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wait for the current step to finish.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable operation energises the motor of node %1: it will hold its position and follow commands.

Make sure the machine is safe to move and people are clear.

Send 6040h = 000Fh now?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable operation was not confirmed; nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: sending… (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 done: the drive is now in %2 (statusword %3h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step “%1” failed: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
The drive was sent Disable voltage (6040h = 0000h) and is now in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
DISABLING FAILED: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What to check: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive does not list %1 as supported (6502h = %2h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Setting the mode of operation: 6060h = %1 (%2), then checking 6061h…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode set and verified: the drive shows %1 in 6061h.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not set %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable the drive first (Operation enabled), then arm the test move.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>While you hold “Hold to run”, the motor of node %1 will %2, for at most %3 ms.
Releasing the button stops it. Make sure the axis is free to move.

Arm the test move?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test move not armed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test move armed: hold the “Hold to run” button to move, release it to stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm the test move first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test move stopped: %1. The drive stays enabled; press Disable when done.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test move failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving while the button is held…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>hold-to-run button released</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop: sending 6040h = 0002h…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quick stop done: the drive is in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disable: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disabling: Shutdown, then Disable voltage…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive is disabled (%1): the motor has no power.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Dry run: %n step(s) the enable would send from %1 — nothing was sent. “Save as script…” keeps them for coscope-cli script run.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Looking for a CiA 402 drive (device type 1000h = …0192h)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No CiA 402 drive answered yet; trying again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>another drive was chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the identity of node %1 (1018h)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 is a %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The state of node %1 is not known: not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive is initialising (Not ready to switch on); waiting for Switch on disabled…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive finished initialising.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 has no statusword 6041h: it is not a CiA 402 drive (%2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read the drive&apos;s state: %1. Check that the drive is powered and connected, and its node-ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error code 603Fh could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is %2, not %3: the drive is not in CANopen control and will ignore the controlword. Set %1 = %3 first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode of operation (6061h): %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsDock</name>
    <message>
        <source>Events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click an event to show its frame in the trace</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsModel</name>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::FrameDetailsView</name>
    <message>
        <source>Field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO transfer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Direction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>upload (read from the server)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>download (write to the server)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>block</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>segmented</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>expedited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Abort reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 (frame %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (frames %2–%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frame %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identifier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Service</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (remote request)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>transmitted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Flags</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>byte %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bytes %1–%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, bit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, bits %1–%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no payload)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthDock</name>
    <message>
        <source>Health</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No frames yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What to look at first, the worst at the top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDOs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Average load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Peak load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus load (%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus load</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) over %1 s; bus load average %2 %, peak %3 % at %4 bit/s; %5 error frame(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthModel</name>
    <message>
        <source>Severity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Beats</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Period min/avg/max ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Late</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boot-ups</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO transfers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO p99 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO aborts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SDO timeouts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Jitter ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Critical</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Info</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>guarding stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>heartbeat stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>guarding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (no consumer)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::JournalOfferBar</name>
    <message>
        <source>Unclosed capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reopen capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A capture was not closed: CoScope ended without closing it (killed, crashed or the power went out). Its journal %1 (%2, last written %3) holds everything received up to about a second before.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::MainWindow</name>
    <message>
        <source>Capture stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open CAN log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save trace as…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export filtered rows…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export filtered rows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export PDO layout as &amp;DBC…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect to &amp;virtual drives (sim://)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Recent connections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Commission</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The default layout applies at the next start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reopened the capture journal %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot connect to %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open log</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A save is already running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only bus: commissioning would transmit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A save is still running; wait for it or cancel it first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsaved capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The trace holds %L1 frames that are not saved. Save the capture first?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %L2 frames, %L3 lines not understood — first: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %L2 frames (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %L1 frames to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 lines, %L4 frames, %L5 lines skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 frames, %L4 records skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No frames were found in this file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>… and %L1 more</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>System language (%1)</source>
        <extracomment>View ▸ Language: follow the operating system&apos;s language; %1 = that language&apos;s own name</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the other windows (wizards, dialogs) to change the language</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdChangePage</name>
    <message>
        <source>What to change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The node-ID (the device&apos;s address on the bus, 1-127) or the baud rate (CAN bit rate).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud rate (bit rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LSS (layer setting services, CiA 305) — works for any LSS-capable device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New node-ID:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New baud rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter %1 over SDO — as its manual describes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter — none documented for this device</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdFindPage</name>
    <message>
        <source>Find the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pick the drive whose node-ID or baud rate (bit rate) you want to change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These are the devices CoScope has seen on the bus. &lt;b&gt;Scan&lt;/b&gt; asks every node-ID 1-127 for its device type and identity (SDO reads, changes nothing). A new device without node-ID (LSS-unconfigured) stays silent: &lt;b&gt;Find device without node-ID&lt;/b&gt; finds it with LSS Fastscan (CiA 305).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device (dictionary)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State (NMT)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find device without node-ID (LSS Fastscan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scanning node-IDs 1-127…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LSS Fastscan: looking for a device without node-ID…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n device(s) known.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>(unknown — LSS only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device type:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(not identified — scan)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target: the device without node-ID found by LSS Fastscan.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Target: node %1%2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device chosen yet.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdRunPage</name>
    <message>
        <source>Dry run: nothing has been sent yet. This is exactly what CoScope will send, and why.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check and change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change it now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sending: CoScope runs the sequence below; each step turns green when the device has answered.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes effect: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CoScope will reconnect at %1 after the first part.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot prepare the change: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent: the sequence below ran to the end. The device has its new setting.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped: the green steps below were sent, the red one failed, the rest was not sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preparing the sequence…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdWizard</name>
    <message>
        <source>Baud rate and node-ID — CoScope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the devices, so connect first (File ▸ Connect).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard cannot change anything. Reconnect without listen-only to use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection was closed while the change was running. Connect again and scan to see where the device is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device without node-ID answered (LSS Fastscan). Every device on the bus has a node-ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Found a device without node-ID: vendor %1h, product %2h, serial %3h. It waits in LSS configuration state for its node-ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a device first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the new node-ID.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device already has node-ID %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node-ID %1 is already used by another device on this bus: two devices with one node-ID break communication.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a bit rate other than the one the bus runs at now (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device without node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; LSS (layer setting services, CiA 305) picks %1 by its identity (1018h) and gives it the new setting; the device stores it itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; CoScope writes the drive&apos;s own parameter %1 over SDO (the way its manual describes).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Takes effect:&lt;/b&gt; %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;About this drive:&lt;/b&gt; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Every other node on this bus&lt;/b&gt; (%1) stays at %2. After the change, %3 only talks at %4: the others cannot reach it until they are changed too. Change them all, one after another, then the bus runs at %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none seen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nodes %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CoScope reconnects at the new bit rate by itself and waits for %1 there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;If it does not come back:&lt;/b&gt; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Cannot do this:&lt;/b&gt; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The change is already running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The sequence is not ready yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection is gone: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped at %1.
The device answered: %2
What to check: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done: the device that was %1 now answers at node-ID %2 (it reported on the bus).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>without node-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done: node %1 now runs at %2 and CoScope is connected at %2. Nodes still at %3 cannot be reached at this rate: change them too, or reconnect at %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection is gone before reconnecting.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reconnecting at %1 (%2)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not reconnect at %1: %2
%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus did not open at %1.
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 now answers at node-ID %2 (Baud rate and node-ID wizard)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesDock</name>
    <message>
        <source>Nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan network (SDO 1000h on nodes 1–127)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Assign dictionary…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dictionary for node %1:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only: commands disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan finished: %1 node(s) answered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A scan is running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only bus: a scan would transmit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read the device type 1000h of every node-ID 1–127, then each answering node&apos;s identity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only: NMT commands are disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to a bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>An NMT command is waiting for your answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send NMT “%1” to %2?

Frame: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send NMT command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT %1 to %2 failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT command failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent NMT %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive %1 is enabled (Operation enabled, statusword 0x%2): %3 stops it abruptly; the motor loses torque or trips its communication-loss reaction (6007h). %4Disable it first (CiA 402 wizard: Disable).

</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delta drives raise AL401 (CANopen communication lost). </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scan needs a connected bus that is not listen-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A scan is already running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read object 1000h from every node-ID 1–127 (SDO upload requests on 601h–67Fh)?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scanning nodes 1–127…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesModel</name>
    <message>
        <source>No heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device name (1008h): %1
Hardware version (1009h): %2
Software version (100Ah): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vendor %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, product %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, product not present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, rev %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, rev not present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, s/n %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, s/n not present</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>boot-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heartbeat age</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identity (1018h)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seen by</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::ObjectDictionaryDock</name>
    <message>
        <source>Object Dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search index or name (6060, 0x1018, heartbeat)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show only the values read from the node that differ from the dictionary&apos;s default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read every readable object of the node over SDO (DOMAINs are skipped)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export DCF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export node %1 as DCF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device configuration (*.dcf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply DCF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply a DCF to node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device configuration (*.dcf *.eds);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write value…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expand all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Collapse all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Listen-only: SDO disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading node %1 stopped: another node was chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dictionary %1 of node %2 cannot be loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;No node selected&lt;/b&gt; — pick one in the Nodes dock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a node in the Nodes dock to see its object dictionary.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Node %1&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · &lt;span style=&apos;color:#b00020&apos;&gt;no dictionary&lt;/span&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · %1 entries, %2 read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · &lt;i&gt;listen-only: no SDO&lt;/i&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> · &lt;i&gt;offline: no SDO&lt;/i&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No dictionary is known for node %1: it was not identified (1018h) or matched none in the library. Assign one to see its objects.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no node selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no dictionary for node %2 (assign one)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the bus is listen-only, nothing is sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not connected to a bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is write-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 %2 %3 = %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write %1 %2 = %3 to node %4?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2 is %3: not writable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write object</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>

SDO download of %n byte(s): %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Node %1 %2 written: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A read or DCF application is already running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading %1 objects of node %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read of node %1 cancelled: %2 values read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1: %2 values read, %3 refused (red rows; the tool tip has the abort text)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1: %2 values read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export of node %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1: %2 values exported to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export: no node with a dictionary selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export: wait for the running read to finish</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply DCF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply DCF: wait for the running read to finish</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a usable DCF: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no object could be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading node %1&apos;s current values of the %2 candidates in %3…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply DCF cancelled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 already has every value of %2 (%3 entries not written)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply DCF: the bus can no longer transmit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing %1 objects to node %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 written, %3 refused — first: %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 objects written%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::OdTreeModel</name>
    <message>
        <source>Index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoApplyPage</name>
    <message>
        <source>Check and apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This is exactly what will be sent, step by step (dry run: nothing has been sent yet). If the drive refuses a step, the wizard stops, tells you why and writes the old settings back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep after power-off: store the drive&apos;s parameters (1010h:01 = &quot;save&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the drive&apos;s process data afterwards (NMT start: operational)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply to the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without this the new mapping is lost when the drive is switched off or reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This drive&apos;s dictionary has no 1010h (store parameters)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applying…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoChoosePage</name>
    <message>
        <source>Which drive and which message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A PDO (process data object) is one CAN message that carries up to 8 bytes of live values. The drive sends its TPDOs (transmit PDOs, e.g. status and position) and receives its RPDOs (receive PDOs, e.g. commands).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — the drive sends (transmit PDO %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — the drive receives (receive PDO %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Byte</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message (PDO):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 (no dictionary)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1 — %2%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for a drive to appear on the bus…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading %1 of node %2 from the drive (SDO upload of %3h and %4h)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not read %1 of node %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN-ID %1h%2. %3. %4 of 64 bits used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (switched off: COB-ID bit 31 set)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dry run (the bus is listen-only, nothing is sent): starting from the dictionary&apos;s defaults, not read from the drive: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Now in the drive: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(nothing mapped: the message is empty)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Good to know about this drive:</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoFrameLayout</name>
    <message>
        <source>byte %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of 64 bits — too long: a PDO carries at most 8 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of 64 bits used (%2 bytes in the frame)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoMappingPage</name>
    <message>
        <source>What the message carries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pick the values to put in the message, in the order they appear in the frame (the PDO mapping). Double-click or drag an object to the right; drag or use Up/Down to reorder. A frame holds at most 8 bytes (64 bits).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Search by name or index, e.g. velocity or 606C</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add →</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>← Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>As in the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start again from the mapping read from the drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Objects this drive allows in the message:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the message, in frame order:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The frame, byte by byte:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no dictionary for this node: objects cannot be listed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1  (%2, %3 bits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1h:%2 — %3, access %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot add: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1  (%2 bits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Too long: %1 bits. Remove objects until the total is 64 bits or less.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing mapped: the message would carry no data.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Same as in the drive now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changed: %1 objects, %2 bits (was %3 objects, %4 bits).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Many drives allow at most 8 objects per PDO.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoTimingPage</name>
    <message>
        <source>When the message is sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose what makes the drive send the message (TPDO) or act on it (RPDO), and the CAN-ID it uses.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On SYNC, every n-th SYNC (synchronous cyclic, type 1–240)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On SYNC, only after a value changed (synchronous acyclic, type 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 255: device profile)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 254: manufacturer)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Other transmission type (e.g. 252/253: only on request, RTR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> SYNC(s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Message switched on (COB-ID bit 31 = 0: PDO valid)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Default</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The pre-defined connection set (CiA 301 §7.3.5): TPDO1 180h + node … RPDO4 500h + node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent when:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Minimum gap (inhibit time):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timer (event timer):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN-ID (COB-ID, hex):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This drive fixes the CAN-ID (COB-ID read-only): it cannot be changed, and the message cannot be switched off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive waits at least this long between two messages (100 µs units on the bus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not available on this drive or for an RPDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event-driven TPDO: sent at least this often; RPDO: the drive reports a timeout when no message came for this long</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not available on this drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Someone must send SYNC (a SYNC producer, object 1005h/1006h) or this message never goes out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The master must send SYNC after the message, every cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event timer off: sent only when a mapped value changes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent when a value changes, and at least every %1 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Never more often than every %1 ms (inhibit time).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CAN-ID %1h is not the default %2h: make sure no other message uses it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The message will be switched off: the drive will neither send nor accept it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AIMOTOR: synchronous PDOs need SYNC from the master.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoWizard</name>
    <message>
        <source>PDO mapping — CoScope</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the drive, so connect first (File ▸ Connect).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard can neither read nor change the drive. Reconnect without listen-only to use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the connection changed while reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The connection was closed while the PDO was being changed. Connect again and read the PDO to see what is in force.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a drive first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PDO has not been read from the drive yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDO mapping: %1 of node %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the settings after power-off: store all parameters (1010h:01 = &quot;save&quot;, CiA 301 §7.5.2.13)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start process data: the drive goes operational and sends/uses its PDOs (NMT start)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A change is already being applied.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped at step %1 of %2: %3%4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the drive answered: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What to check: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The previous settings were written back: %1 works as before (%2 objects, %3 bits). The drive was left pre-operational.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the previous settings back failed as well (%1): read the PDO again and check it before starting the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was changed on the drive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done: %1 of node %2 now carries %3 objects (%4 bits), checked by reading back. The trace and the plot decode it with the new layout from now on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> The drive is pre-operational: start it (NMT start) to make PDOs flow.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Starting the drive failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> The drive was started (operational).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>
But storing failed (%1): the new mapping works now and is lost at power-off. %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Stored in the drive (kept after power-off).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotDock</name>
    <message>
        <source>Plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rolling window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Whole trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow the newest samples over a window of seconds, or show the whole trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Width of the rolling window</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Freeze the view (data keeps being recorded); zoom and pan pause too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stacked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shared plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stacked plots sharing the time axis, or one plot with a y-axis per signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the y-axes to the visible data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Auto Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the y-axes fitted; off: drag and wheel zoom the y-axes too</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Legend</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear cursors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add raw signal…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot bits of any frame (start bit, length, type, byte order, factor, offset, unit): for devices without a dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF document…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV of the visible window…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No frames from the bus yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the log…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The log holds no frames.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to plot: connect to a bus (Bus menu) or open a log (File ▸ Open log…).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bus %1 node %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No PDOs in this trace (%L1 frames): the plot shows the objects that PDOs carry.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nodes seen: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nodes send their PDOs once started (Nodes dock: right-click ▸ Start).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No dictionary for these nodes, so their PDOs cannot be decoded: %1. Assign one in the Nodes dock (right-click the node ▸ Assign dictionary…)%2; its PDO signals are then listed here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> or identify the nodes with Bus ▸ Scan network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDOs whose mapping is not known (changed before the trace began): %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Raw signal %1 added: it is listed under COB-ID %2h once its frames are read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot write the PNG image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: cannot write the PDF document</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot exported to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotView</name>
    <message>
        <source>Pick signals on the left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click the plot to place cursor A (jumps to the frame), Shift+click for cursor B.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::RawSignalDialog</name>
    <message>
        <source>Add raw signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0x181</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The frame&apos;s identifier: decimal or 0x hex; over 7FFh a 29-bit identifier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Intel: the least significant bit; Motorola: the most significant bit (DBC numbering, bit 7 of byte 0 = 7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unsigned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Float (IEEE 754, 32 or 64 bits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Intel (little-endian, as CANopen PDOs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Motorola (big-endian)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value = raw × factor + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Byte order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot bits of any frame, for a device without a dictionary.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give the signal a name.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The COB-ID must be a number up to 1FFFFFFFh (0x181, 385 or 181h).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The factor must be a number other than 0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The offset must be a number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A float is 32 or 64 bits long.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The signal ends past byte 64 of the frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This signal cannot be read: %1.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptPreview</name>
    <message>
        <source>What it does</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Script line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save as script…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write these steps to a text file that `coscope-cli script run BUS FILE` replays</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n step(s) will be sent</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n step(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save as script</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command scripts (*.txt);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save the script: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptRunPanel</name>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped: the connection changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Send these commands?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A run is in progress.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus cannot send now.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step %1 of %2…</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Done: %n step(s) completed.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped at step %1; nothing further was sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failed at %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::SignalPicker</name>
    <message>
        <source>Search signals (name, object, node)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Factor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No signal matches “%1”.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus %1, COB-ID %2h (raw signals)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>COB-ID %1h (raw signals)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus %1, node %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value = raw × factor + %1 (defined: × %2 %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>value = raw × factor (dictionary: %1 %2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceDock</name>
    <message>
        <source>Trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close this report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow new frames (scrolling up pauses)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Absolute time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Relative time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delta time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Latest per ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One row per COB-ID showing its latest frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group SDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Group SDO transfers: each transfer as one row; click its ▸ to show its frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter: node:5 svc:sdo,emcy id:580-5FF text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Find next</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bookmark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Toggle a bookmark on the selected frame (Ctrl+B); F2 / Shift+F2 jump</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 rows, %L2 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 SDO transfers grouped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 of %L2 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found: the trace is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found in the next %L2 rows; search again to continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select a frame to bookmark</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No bookmarks (Ctrl+B sets one)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceModel</name>
    <message>
        <source>Click to expand or collapse the transfer&apos;s frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Δt (s)</source>
        <extracomment>Trace column: time since the previous frame, in seconds</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No.</source>
        <extracomment>Trace columns: frame number, time, bus, COB-ID, node, CANopen service, direction (Rx/Tx), data length, data bytes, decoded summary</extracomment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Node</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Service</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dir</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Len</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Summary</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardFramesPane</name>
    <message>
        <source>Frames on the bus for this wizard</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardGuard</name>
    <message>
        <source>No bus is connected, so nothing can be sent. Connect to the bus first; you can still prepare the steps and save them as a script.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is open in listen-only mode: CoScope never transmits on it. Reconnect without listen-only to send these commands; you can still prepare the steps and save them as a script.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is still opening; sending is possible once it is open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bus is not open (%1), so nothing can be sent.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>coscope::gui::Workspace</name>
    <message>
        <source>cannot create the folder %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The capture is not journaled to disk (%1); it is kept in memory only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture stopped: cannot write the capture journal %1 (%2). The trace keeps the %L3 frames received.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
