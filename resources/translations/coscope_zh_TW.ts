<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_TW">
<context>
    <name>AboutBox</name>
    <message>
        <source>CANopen bus analyzer and servo-drive commissioning tool.</source>
        <translation>CANopen 匯流排分析與伺服驅動器調機工具。</translation>
    </message>
    <message>
        <source>Version %1, source revision %2, built with Qt %3 (running on Qt %4).</source>
        <translation>版本 %1，原始碼修訂 %2，以 Qt %3 建置（執行於 Qt %4）。</translation>
    </message>
    <message>
        <source>CoScope is free software under the GNU General Public License, version 3 or later (GPL-3.0-or-later), and comes with no warranty.</source>
        <translation>CoScope 是依 GNU 通用公共授權條款第 3 版或更新版本（GPL-3.0-or-later）發布的自由軟體，不提供任何擔保。</translation>
    </message>
    <message>
        <source>It is built on:</source>
        <translation>它建立在以下軟體之上：</translation>
    </message>
    <message>
        <source>Qt, under the GNU Lesser General Public License version 3 (LGPLv3)</source>
        <translation>Qt，依 GNU 較寬鬆通用公共授權條款第 3 版（LGPLv3）</translation>
    </message>
    <message>
        <source>QCustomPlot, under the GNU General Public License version 3 (GPLv3)</source>
        <translation>QCustomPlot，依 GNU 通用公共授權條款第 3 版（GPLv3）</translation>
    </message>
    <message>
        <source>spdlog and fmt, under the MIT license</source>
        <translation>spdlog 與 fmt，依 MIT 授權條款</translation>
    </message>
    <message>
        <source>About CoScope</source>
        <translation>關於 CoScope</translation>
    </message>
</context>
<context>
    <name>ApplyText</name>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Node %1 (%2)</source>
        <translation>節點 %1（%2）</translation>
    </message>
    <message>
        <source>the node does not answer</source>
        <translation>節點沒有回應</translation>
    </message>
    <message>
        <source>another device answers at this node-ID</source>
        <translation>此節點 ID 由其他裝置回應</translation>
    </message>
    <message>
        <source>not in the project</source>
        <translation>不在專案中</translation>
    </message>
    <message>
        <source>no dictionary for the node (%1)</source>
        <translation>此節點沒有字典（%1）</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <source>nothing to write, already as in the project</source>
        <translation>無需寫入，已與專案相同</translation>
    </message>
    <message>
        <source>refused, old values put back</source>
        <translation>被拒絕，已寫回舊值</translation>
    </message>
    <message>
        <source>refused, old values NOT all put back</source>
        <translation>被拒絕，舊值「未」全部寫回</translation>
    </message>
    <message>
        <source>not written: a node before refused</source>
        <translation>未寫入：先前的節點拒絕了寫入</translation>
    </message>
    <message>
        <source>skipped</source>
        <translation>已略過</translation>
    </message>
    <message>
        <source>%1: not written: %2</source>
        <translation>%1：未寫入：%2</translation>
    </message>
    <message numerus="yes">
        <source>%1: %n SDO write(s)</source>
        <translation>
            <numerusform>%1：%n 筆 SDO 寫入</numerusform>
        </translation>
    </message>
    <message>
        <source>write %1 %2 = %3</source>
        <translation>寫入 %1 %2 = %3</translation>
    </message>
    <message>
        <source>%1  (now %2)</source>
        <translation>%1  （目前 %2）</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <source> - %n object(s) written</source>
        <translation>
            <numerusform> - 已寫入 %n 個物件</numerusform>
        </translation>
    </message>
    <message>
        <source>written: %1</source>
        <translation>已寫入：%1</translation>
    </message>
    <message>
        <source>REFUSED: %1: %2</source>
        <translation>被拒絕：%1：%2</translation>
    </message>
    <message>
        <source>put back: %1</source>
        <translation>已寫回：%1</translation>
    </message>
    <message>
        <source>NOT put back: %1: %2</source>
        <translation>未寫回：%1：%2</translation>
    </message>
</context>
<context>
    <name>CoreText</name>
    <message>
        <source>Not ready to switch on</source>
        <translation>初始化中</translation>
    </message>
    <message>
        <source>Switch on disabled</source>
        <translation>禁止啟動</translation>
    </message>
    <message>
        <source>Ready to switch on</source>
        <translation>準備啟動</translation>
    </message>
    <message>
        <source>Switched on</source>
        <translation>已啟動</translation>
    </message>
    <message>
        <source>Operation enabled</source>
        <translation>運轉致能</translation>
    </message>
    <message>
        <source>Quick stop active</source>
        <translation>快速停止中</translation>
    </message>
    <message>
        <source>Fault reaction active</source>
        <translation>故障反應中</translation>
    </message>
    <message>
        <source>Fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <source>Unknown state</source>
        <translation>未知狀態</translation>
    </message>
    <message>
        <source>ready to switch on</source>
        <translation>準備啟動</translation>
    </message>
    <message>
        <source>switched on</source>
        <translation>已啟動</translation>
    </message>
    <message>
        <source>operation enabled</source>
        <translation>運轉致能</translation>
    </message>
    <message>
        <source>fault</source>
        <translation>故障</translation>
    </message>
    <message>
        <source>voltage enabled</source>
        <translation>電壓已啟用</translation>
    </message>
    <message>
        <source>quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>switch on disabled</source>
        <translation>禁止啟動</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 8)</source>
        <translation>製造商定義（位元 8）</translation>
    </message>
    <message>
        <source>remote</source>
        <translation>遠端</translation>
    </message>
    <message>
        <source>target reached</source>
        <translation>已到達目標</translation>
    </message>
    <message>
        <source>internal limit active</source>
        <translation>內部限制作用中</translation>
    </message>
    <message>
        <source>operation mode specific (bit 12)</source>
        <translation>依操作模式而定（位元 12）</translation>
    </message>
    <message>
        <source>operation mode specific (bit 13)</source>
        <translation>依操作模式而定（位元 13）</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 14)</source>
        <translation>製造商定義（位元 14）</translation>
    </message>
    <message>
        <source>manufacturer specific (bit 15)</source>
        <translation>製造商定義（位元 15）</translation>
    </message>
    <message>
        <source>Shutdown</source>
        <translation>關閉（Shutdown）</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>啟動（Switch on）</translation>
    </message>
    <message>
        <source>Switch on + enable operation</source>
        <translation>啟動＋運轉致能</translation>
    </message>
    <message>
        <source>Disable voltage</source>
        <translation>切斷電壓（Disable voltage）</translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>Disable operation</source>
        <translation>禁止運轉（Disable operation）</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>運轉致能</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>故障重置</translation>
    </message>
    <message>
        <source>Switch on / disable operation</source>
        <translation>啟動／禁止運轉</translation>
    </message>
    <message>
        <source>No command</source>
        <translation>無命令</translation>
    </message>
    <message>
        <source>No mode</source>
        <translation>無模式</translation>
    </message>
    <message>
        <source>Profile position (PP)</source>
        <translation>輪廓位置（PP）</translation>
    </message>
    <message>
        <source>Velocity (VL)</source>
        <translation>速度（VL）</translation>
    </message>
    <message>
        <source>Profile velocity (PV)</source>
        <translation>輪廓速度（PV）</translation>
    </message>
    <message>
        <source>Profile torque (PT)</source>
        <translation>輪廓扭矩（PT）</translation>
    </message>
    <message>
        <source>Homing (HM)</source>
        <translation>原點復歸（HM）</translation>
    </message>
    <message>
        <source>Interpolated position (IP)</source>
        <translation>補間位置（IP）</translation>
    </message>
    <message>
        <source>Cyclic synchronous position (CSP)</source>
        <translation>週期同步位置（CSP）</translation>
    </message>
    <message>
        <source>Cyclic synchronous velocity (CSV)</source>
        <translation>週期同步速度（CSV）</translation>
    </message>
    <message>
        <source>Cyclic synchronous torque (CST)</source>
        <translation>週期同步扭矩（CST）</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>啟動</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Enter pre-operational</source>
        <translation>進入預操作狀態</translation>
    </message>
    <message>
        <source>Reset node</source>
        <translation>重置節點</translation>
    </message>
    <message>
        <source>Reset communication</source>
        <translation>重置通訊</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>上線（Boot-up）</translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Operational</source>
        <translation>操作狀態</translation>
    </message>
    <message>
        <source>Pre-operational</source>
        <translation>預操作狀態</translation>
    </message>
    <message>
        <source>Toggle bit not alternated</source>
        <translation>切換位元未交替</translation>
    </message>
    <message>
        <source>SDO protocol timed out</source>
        <translation>SDO 協定逾時</translation>
    </message>
    <message>
        <source>Client/server command specifier not valid or unknown</source>
        <translation>用戶端／伺服器命令識別碼無效或未知</translation>
    </message>
    <message>
        <source>Invalid block size (block mode only)</source>
        <translation>區塊大小無效（僅限區塊模式）</translation>
    </message>
    <message>
        <source>Invalid sequence number (block mode only)</source>
        <translation>序號無效（僅限區塊模式）</translation>
    </message>
    <message>
        <source>CRC error (block mode only)</source>
        <translation>CRC 錯誤（僅限區塊模式）</translation>
    </message>
    <message>
        <source>Out of memory</source>
        <translation>記憶體不足</translation>
    </message>
    <message>
        <source>Unsupported access to an object</source>
        <translation>不支援的物件存取方式</translation>
    </message>
    <message>
        <source>Attempt to read a write-only object</source>
        <translation>嘗試讀取唯寫物件</translation>
    </message>
    <message>
        <source>Attempt to write a read-only object</source>
        <translation>嘗試寫入唯讀物件</translation>
    </message>
    <message>
        <source>Object does not exist in the object dictionary</source>
        <translation>物件字典中沒有此物件</translation>
    </message>
    <message>
        <source>Object cannot be mapped to the PDO</source>
        <translation>物件無法映射到 PDO</translation>
    </message>
    <message>
        <source>The number and length of the objects to be mapped would exceed the PDO length</source>
        <translation>要映射的物件數量與長度會超過 PDO 長度</translation>
    </message>
    <message>
        <source>General parameter incompatibility reason</source>
        <translation>一般性參數不相容</translation>
    </message>
    <message>
        <source>General internal incompatibility in the device</source>
        <translation>裝置內部一般性不相容</translation>
    </message>
    <message>
        <source>Access failed due to a hardware error</source>
        <translation>硬體錯誤導致存取失敗</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter does not match</source>
        <translation>資料類型不符，服務參數長度不符</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too high</source>
        <translation>資料類型不符，服務參數長度過長</translation>
    </message>
    <message>
        <source>Data type does not match, length of service parameter too low</source>
        <translation>資料類型不符，服務參數長度過短</translation>
    </message>
    <message>
        <source>Sub-index does not exist</source>
        <translation>子索引不存在</translation>
    </message>
    <message>
        <source>Invalid value for parameter (download only)</source>
        <translation>參數值無效（僅限下載）</translation>
    </message>
    <message>
        <source>Value of parameter written too high (download only)</source>
        <translation>寫入的參數值過高（僅限下載）</translation>
    </message>
    <message>
        <source>Value of parameter written too low (download only)</source>
        <translation>寫入的參數值過低（僅限下載）</translation>
    </message>
    <message>
        <source>Maximum value is less than minimum value</source>
        <translation>最大值小於最小值</translation>
    </message>
    <message>
        <source>Resource not available: SDO connection</source>
        <translation>資源不可用：SDO 連線</translation>
    </message>
    <message>
        <source>General error</source>
        <translation>一般錯誤</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application</source>
        <translation>資料無法傳送或儲存到應用程式</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of local control</source>
        <translation>因本地控制，資料無法傳送或儲存到應用程式</translation>
    </message>
    <message>
        <source>Data cannot be transferred or stored to the application because of the present device state</source>
        <translation>因裝置目前的狀態，資料無法傳送或儲存到應用程式</translation>
    </message>
    <message>
        <source>Object dictionary dynamic generation fails or no object dictionary is present</source>
        <translation>物件字典動態產生失敗，或沒有物件字典</translation>
    </message>
    <message>
        <source>No data available</source>
        <translation>沒有可用的資料</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已關閉</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>開啟中</translation>
    </message>
    <message>
        <source>open</source>
        <translation>已開啟</translation>
    </message>
    <message>
        <source>error</source>
        <translation>錯誤</translation>
    </message>
    <message>
        <source>NMT %1, node %2</source>
        <translation>NMT %1，節點 %2</translation>
    </message>
    <message>
        <source>NMT %1, all nodes</source>
        <translation>NMT %1，所有節點</translation>
    </message>
    <message>
        <source>NMT (malformed)</source>
        <translation>NMT（格式錯誤）</translation>
    </message>
    <message>
        <source>NMT command with %1 bytes; CiA 301 requires 2</source>
        <translation>NMT 命令有 %1 位元組；CiA 301 規定為 2</translation>
    </message>
    <message>
        <source>unknown NMT command specifier 0x%1</source>
        <translation>未知的 NMT 命令碼 0x%1</translation>
    </message>
    <message>
        <source>NMT target node-ID %1 is outside 0..127</source>
        <translation>NMT 目標節點 ID %1 不在 0..127 之間</translation>
    </message>
    <message>
        <source>Node guarding request, node %1</source>
        <translation>節點保護請求，節點 %1</translation>
    </message>
    <message>
        <source>error control frame with %1 bytes; CiA 301 requires 1</source>
        <translation>錯誤控制封包有 %1 位元組；CiA 301 規定為 1</translation>
    </message>
    <message>
        <source>Error control (malformed), node %1</source>
        <translation>錯誤控制（格式錯誤），節點 %1</translation>
    </message>
    <message>
        <source>unknown NMT state 0x%1</source>
        <translation>未知的 NMT 狀態 0x%1</translation>
    </message>
    <message>
        <source>node guarding toggle bit did not alternate (still %1)</source>
        <translation>節點保護的切換位元沒有交替（仍為 %1）</translation>
    </message>
    <message>
        <source>Boot-up, node %1</source>
        <translation>上線訊息，節點 %1</translation>
    </message>
    <message>
        <source>Node guarding, node %1: %2, toggle %3</source>
        <translation>節點保護，節點 %1：%2，切換位元 %3</translation>
    </message>
    <message>
        <source>Heartbeat, node %1: %2</source>
        <translation>心跳，節點 %1：%2</translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation>SYNC 計數 %1</translation>
    </message>
    <message>
        <source>SYNC with %1 bytes; CiA 301 allows 0 or 1</source>
        <translation>SYNC 有 %1 位元組；CiA 301 只允許 0 或 1</translation>
    </message>
    <message>
        <source>SYNC counter %1 is outside 1..240</source>
        <translation>SYNC 計數 %1 不在 1..240 之間</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, register 0x%4</source>
        <translation>EMCY 節點 %1：%2 %3，錯誤暫存器 0x%4</translation>
    </message>
    <message>
        <source>EMCY (malformed), node %1</source>
        <translation>EMCY（格式錯誤），節點 %1</translation>
    </message>
    <message>
        <source>EMCY with %1 bytes; CiA 301 requires 8</source>
        <translation>EMCY 有 %1 位元組；CiA 301 規定為 8</translation>
    </message>
    <message>
        <source>M%1 alarm %2</source>
        <translation>M%1 異警 %2</translation>
    </message>
    <message>
        <source>%1 0x%2 (not in the table)</source>
        <translation>%1 0x%2（不在異警表中）</translation>
    </message>
    <message>
        <source>SDO write node %1 %2 = %3</source>
        <translation>SDO 寫入 節點 %1 %2 = %3</translation>
    </message>
    <message>
        <source>SDO write node %1 %2, %3 bytes (segmented)</source>
        <translation>SDO 寫入 節點 %1 %2，%3 位元組（分段）</translation>
    </message>
    <message>
        <source>SDO write node %1 %2 (segmented)</source>
        <translation>SDO 寫入 節點 %1 %2（分段）</translation>
    </message>
    <message>
        <source>SDO write ok node %1 %2</source>
        <translation>SDO 寫入成功 節點 %1 %2</translation>
    </message>
    <message>
        <source>SDO read node %1 %2 = %3</source>
        <translation>SDO 讀取 節點 %1 %2 = %3</translation>
    </message>
    <message>
        <source>SDO read node %1 %2, %3 bytes (segmented)</source>
        <translation>SDO 讀取 節點 %1 %2，%3 位元組（分段）</translation>
    </message>
    <message>
        <source>SDO read node %1 %2 (segmented)</source>
        <translation>SDO 讀取 節點 %1 %2（分段）</translation>
    </message>
    <message>
        <source>SDO read node %1 %2</source>
        <translation>SDO 讀取 節點 %1 %2</translation>
    </message>
    <message>
        <source>SDO abort node %1 %2: %3 %4</source>
        <translation>SDO 中止 節點 %1 %2：%3 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2, toggle %3, %4 bytes, last</source>
        <translation>SDO %1 節點 %2，切換位元 %3，%4 位元組，最後一段</translation>
    </message>
    <message>
        <source>SDO %1 node %2, toggle %3, %4 bytes</source>
        <translation>SDO %1 節點 %2，切換位元 %3，%4 位元組</translation>
    </message>
    <message>
        <source>SDO block segment %1 node %2, %3 bytes, last</source>
        <translation>SDO 區塊分段 %1 節點 %2，%3 位元組，最後一段</translation>
    </message>
    <message>
        <source>SDO block segment %1 node %2, %3 bytes</source>
        <translation>SDO 區塊分段 %1 節點 %2，%3 位元組</translation>
    </message>
    <message>
        <source>SDO %1 node %2, ackseq %3, block size %4</source>
        <translation>SDO %1 節點 %2，確認序號 %3，區塊大小 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2, %3 unused bytes, CRC 0x%4</source>
        <translation>SDO %1 節點 %2，%3 個未使用位元組，CRC 0x%4</translation>
    </message>
    <message>
        <source>SDO node %1 (invalid)</source>
        <translation>SDO 節點 %1（無效）</translation>
    </message>
    <message>
        <source>SDO remote frame, node %1</source>
        <translation>SDO 遠程封包，節點 %1</translation>
    </message>
    <message>
        <source>remote frame on an SDO COB-ID</source>
        <translation>SDO COB-ID 上出現遠程封包</translation>
    </message>
    <message>
        <source>unknown abort code</source>
        <translation>未知的中止碼</translation>
    </message>
    <message>
        <source>initiate download request</source>
        <translation>起始下載請求</translation>
    </message>
    <message>
        <source>download segment request</source>
        <translation>下載分段請求</translation>
    </message>
    <message>
        <source>initiate upload request</source>
        <translation>起始上傳請求</translation>
    </message>
    <message>
        <source>upload segment request</source>
        <translation>上傳分段請求</translation>
    </message>
    <message>
        <source>initiate download response</source>
        <translation>起始下載回應</translation>
    </message>
    <message>
        <source>download segment response</source>
        <translation>下載分段回應</translation>
    </message>
    <message>
        <source>initiate upload response</source>
        <translation>起始上傳回應</translation>
    </message>
    <message>
        <source>upload segment response</source>
        <translation>上傳分段回應</translation>
    </message>
    <message>
        <source>block upload initiate</source>
        <translation>區塊上傳起始</translation>
    </message>
    <message>
        <source>block upload start</source>
        <translation>區塊上傳開始</translation>
    </message>
    <message>
        <source>block upload ack</source>
        <translation>區塊上傳確認</translation>
    </message>
    <message>
        <source>block upload end</source>
        <translation>區塊上傳結束</translation>
    </message>
    <message>
        <source>block upload end response</source>
        <translation>區塊上傳結束回應</translation>
    </message>
    <message>
        <source>block upload initiate response</source>
        <translation>區塊上傳起始回應</translation>
    </message>
    <message>
        <source>block download initiate</source>
        <translation>區塊下載起始</translation>
    </message>
    <message>
        <source>block download initiate response</source>
        <translation>區塊下載起始回應</translation>
    </message>
    <message>
        <source>block download ack</source>
        <translation>區塊下載確認</translation>
    </message>
    <message>
        <source>block download end</source>
        <translation>區塊下載結束</translation>
    </message>
    <message>
        <source>block download end response</source>
        <translation>區塊下載結束回應</translation>
    </message>
    <message>
        <source>%1 node %2: remote request</source>
        <translation>%1 節點 %2：遠程請求</translation>
    </message>
    <message>
        <source>%1 of node %2 is not valid (COB-ID 0x%3) but was seen on the bus</source>
        <translation>節點 %2 的 %1 無效（COB-ID 0x%3），卻出現在匯流排上</translation>
    </message>
    <message>
        <source>%1 has %2 bytes but its mapping needs %3</source>
        <translation>%1 有 %2 位元組，但它的映射需要 %3</translation>
    </message>
    <message>
        <source>not CANopen (29-bit identifier)</source>
        <translation>不是 CANopen（29 位元識別碼）</translation>
    </message>
    <message>
        <source>unknown COB-ID</source>
        <translation>未知的 COB-ID</translation>
    </message>
    <message>
        <source>new SDO request for %1 while the transfer of %2 was unfinished (abandoned)</source>
        <translation>%2 的傳輸尚未完成時又出現 %1 的 SDO 請求（已放棄前者）</translation>
    </message>
    <message>
        <source>response for %1 but the request was for %2</source>
        <translation>回應的是 %1，但請求的是 %2</translation>
    </message>
    <message>
        <source>SDO transfer of %1 carried %2 bytes but announced %3</source>
        <translation>%1 的 SDO 傳輸帶了 %2 位元組，但宣告為 %3</translation>
    </message>
    <message>
        <source>block ack acknowledges %1 segments, %2 were sent</source>
        <translation>區塊確認了 %1 個分段，實際送出 %2 個</translation>
    </message>
    <message>
        <source>SDO block CRC 0x%1 does not match the data (0x%2)</source>
        <translation>SDO 區塊 CRC 0x%1 與資料不符（0x%2）</translation>
    </message>
    <message>
        <source>unexpected SDO %1 (%2)</source>
        <translation>非預期的 SDO %1（%2）</translation>
    </message>
    <message>
        <source>no transfer in progress</source>
        <translation>沒有進行中的傳輸</translation>
    </message>
    <message>
        <source>transfer of %1 in progress</source>
        <translation>%1 的傳輸進行中</translation>
    </message>
    <message>
        <source>SDO toggle bit %1, expected %2</source>
        <translation>SDO 切換位元為 %1，預期為 %2</translation>
    </message>
    <message>
        <source>abort names %1 but the transfer in progress is %2</source>
        <translation>中止指的是 %1，但進行中的傳輸是 %2</translation>
    </message>
    <message>
        <source>block segment %1, expected %2</source>
        <translation>區塊分段 %1，預期為 %2</translation>
    </message>
    <message>
        <source>block segment %1 beyond the block size %2</source>
        <translation>區塊分段 %1 超出區塊大小 %2</translation>
    </message>
    <message>
        <source>generic error</source>
        <translation>一般錯誤</translation>
    </message>
    <message>
        <source>current</source>
        <translation>電流</translation>
    </message>
    <message>
        <source>voltage</source>
        <translation>電壓</translation>
    </message>
    <message>
        <source>temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <source>communication error</source>
        <translation>通訊錯誤</translation>
    </message>
    <message>
        <source>device profile specific</source>
        <translation>裝置規範定義</translation>
    </message>
    <message>
        <source>reserved</source>
        <translation>保留</translation>
    </message>
    <message>
        <source>manufacturer specific</source>
        <translation>製造商自訂</translation>
    </message>
    <message>
        <source>once</source>
        <translation>1 次</translation>
    </message>
    <message>
        <source>%1 times</source>
        <translation>%1 次</translation>
    </message>
    <message>
        <source>node %1 (bus %2)</source>
        <translation>節點 %1（匯流排 %2）</translation>
    </message>
    <message>
        <source>node %1 rebooted %2 (boot-up without an NMT reset)</source>
        <translation>節點 %1 重新啟動了 %2（沒有 NMT 重置卻送出上線訊息）</translation>
    </message>
    <message>
        <source>node %1 heartbeat stopped: nothing for %2 (period %3)</source>
        <translation>節點 %1 心跳停止：%2 沒有任何訊息（週期 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat stopped: nothing for %2 (period %3), 1017h was set to 0</source>
        <translation>節點 %1 心跳停止：%2 沒有任何訊息（週期 %3），1017h 已被設為 0</translation>
    </message>
    <message>
        <source>node %1 guarding stopped: nothing for %2 (period %3)</source>
        <translation>節點 %1 節點保護停止：%2 沒有任何訊息（週期 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat lost %2 (longest gap %3, period %4)</source>
        <translation>節點 %1 心跳遺失 %2（最長間隔 %3，週期 %4）</translation>
    </message>
    <message>
        <source>node %1 guarding lost %2 (longest gap %3, period %4)</source>
        <translation>節點 %1 節點保護遺失 %2（最長間隔 %3，週期 %4）</translation>
    </message>
    <message>
        <source>%1 more EMCY from node %2</source>
        <translation>節點 %2 還有 %1 筆 EMCY</translation>
    </message>
    <message>
        <source>EMCY %1 %2 from node %3 at %4</source>
        <translation>EMCY %1 %2，來自節點 %3，時間 %4</translation>
    </message>
    <message>
        <source>node %1 left %2 SDO request unanswered</source>
        <translation>節點 %1 有 %2 個 SDO 請求沒有回應</translation>
    </message>
    <message>
        <source>node %1 left %2 SDO requests unanswered</source>
        <translation>節點 %1 有 %2 個 SDO 請求沒有回應</translation>
    </message>
    <message>
        <source>node %1 aborted SDO %2 with %3 %4</source>
        <translation>節點 %1 以 %3 %4 中止 SDO %2</translation>
    </message>
    <message>
        <source>node %1 answered SDO in %2 p99 (max %3)</source>
        <translation>節點 %1 的 SDO 回應時間 p99 為 %2（最大 %3）</translation>
    </message>
    <message>
        <source>node %1 heartbeat late %2 (over 1.5x the %3 period)</source>
        <translation>節點 %1 心跳延遲 %2（超過週期 %3 的 1.5 倍）</translation>
    </message>
    <message>
        <source>node %1 guarding late %2 (over 1.5x the %3 period)</source>
        <translation>節點 %1 節點保護延遲 %2（超過週期 %3 的 1.5 倍）</translation>
    </message>
    <message>
        <source>%1 CAN error frame</source>
        <translation>%1 個 CAN 錯誤封包</translation>
    </message>
    <message>
        <source>%1 CAN error frames</source>
        <translation>%1 個 CAN 錯誤封包</translation>
    </message>
    <message>
        <source>%1 SYNC cycle missing (period %2)</source>
        <translation>缺少 %1 個 SYNC 週期（週期 %2）</translation>
    </message>
    <message>
        <source>%1 SYNC cycles missing (period %2)</source>
        <translation>缺少 %1 個 SYNC 週期（週期 %2）</translation>
    </message>
    <message>
        <source>bus load peaks at %1 % (average %2 %) at %3 bit/s</source>
        <translation>匯流排負載峰值 %1 %（平均 %2 %），鮑率 %3 bit/s</translation>
    </message>
    <message>
        <source>RPDO (%1) sent to node %2, which never answers</source>
        <translation>RPDO（%1）送往節點 %2，但它從未回應</translation>
    </message>
    <message>
        <source>TPDO (%1) sent to node %2, which never answers</source>
        <translation>TPDO（%1）送往節點 %2，但它從未回應</translation>
    </message>
    <message>
        <source>%1 of node %2 (%3) every %4 jitters by %5</source>
        <translation>節點 %2 的 %1（%3）每 %4 一次，抖動 %5</translation>
    </message>
    <message>
        <source>RPDO%1 of node %2 (%3) is valid but nobody sends it</source>
        <translation>節點 %2 的 RPDO%1（%3）有效，但沒有人送出它</translation>
    </message>
    <message>
        <source>%1 node-ID (%2..%3) got an SDO request and never answered: a network scan, or devices missing</source>
        <translation>%1 個節點 ID（%2..%3）收到 SDO 請求卻從未回應：可能是網路掃描，或裝置不在</translation>
    </message>
    <message>
        <source>%1 node-IDs (%2..%3) got an SDO request and never answered: a network scan, or devices missing</source>
        <translation>%1 個節點 ID（%2..%3）收到 SDO 請求卻從未回應：可能是網路掃描，或裝置不在</translation>
    </message>
    <message>
        <source>%1 frame is not CANopen</source>
        <translation>%1 個封包不是 CANopen</translation>
    </message>
    <message>
        <source>%1 frames are not CANopen</source>
        <translation>%1 個封包不是 CANopen</translation>
    </message>
    <message>
        <source>Write %1 = %2 on node %3</source>
        <translation>在節點 %3 寫入 %1 = %2</translation>
    </message>
    <message>
        <source>Read %1 from node %2</source>
        <translation>從節點 %2 讀取 %1</translation>
    </message>
    <message>
        <source>Check %1 = %2 on node %3</source>
        <translation>確認節點 %3 的 %1 = %2</translation>
    </message>
    <message>
        <source>Check %1 = %2 (mask %3) on node %4</source>
        <translation>確認節點 %4 的 %1 = %2（遮罩 %3）</translation>
    </message>
    <message>
        <source>NMT %1 to all nodes</source>
        <translation>對所有節點送出 NMT %1</translation>
    </message>
    <message>
        <source>NMT %1 to node %2</source>
        <translation>對節點 %2 送出 NMT %1</translation>
    </message>
    <message>
        <source>LSS: every device to configuration state</source>
        <translation>LSS：所有裝置進入設定狀態</translation>
    </message>
    <message>
        <source>LSS: every device back to waiting state</source>
        <translation>LSS：所有裝置回到等待狀態</translation>
    </message>
    <message>
        <source>LSS: select the device with vendor %1h, product %2h, revision %3h, serial %4h</source>
        <translation>LSS：選取廠商 %1h、產品 %2h、版本 %3h、序號 %4h 的裝置</translation>
    </message>
    <message>
        <source>LSS: set node-ID to unconfigured (FFh)</source>
        <translation>LSS：將節點 ID 設為未設定（FFh）</translation>
    </message>
    <message>
        <source>LSS: set node-ID %1</source>
        <translation>LSS：設定節點 ID 為 %1</translation>
    </message>
    <message>
        <source>LSS: set bit rate %1</source>
        <translation>LSS：設定鮑率為 %1</translation>
    </message>
    <message>
        <source>LSS: store configuration</source>
        <translation>LSS：儲存設定</translation>
    </message>
    <message>
        <source>LSS: switch to the new bit rate (switch delay %1 ms)</source>
        <translation>LSS：切換到新鮑率（切換延遲 %1 ms）</translation>
    </message>
    <message>
        <source>Wait %1 ms</source>
        <translation>等待 %1 ms</translation>
    </message>
    <message>
        <source>Wait up to %1 ms for node %2 (boot-up or heartbeat)</source>
        <translation>最多等待 %1 ms，直到節點 %2 回報（上線訊息或心跳）</translation>
    </message>
    <message>
        <source>Reconnect the adapter at %1</source>
        <translation>以 %1 重新連接轉接器</translation>
    </message>
    <message>
        <source>Switch %1 off while it is changed (COB-ID bit 31 = 1: PDO not valid)</source>
        <translation>修改期間先關閉 %1（COB-ID 位元 31 = 1：PDO 無效）</translation>
    </message>
    <message>
        <source>When the message is sent: type %1 (transmission type)</source>
        <translation>訊息何時送出：類型 %1（傳輸類型）</translation>
    </message>
    <message>
        <source>Minimum gap between two messages: %1 ms (inhibit time, 100 µs units)</source>
        <translation>兩筆訊息之間的最短間隔：%1 ms（禁止時間，單位 100 µs）</translation>
    </message>
    <message>
        <source>No minimum gap between two messages (inhibit time = 0)</source>
        <translation>兩筆訊息之間不設最短間隔（禁止時間 = 0）</translation>
    </message>
    <message>
        <source>Send at least every %1 ms (event timer)</source>
        <translation>至少每 %1 ms 送出一次（事件計時器）</translation>
    </message>
    <message>
        <source>No timer: sent only on its trigger (event timer = 0)</source>
        <translation>不使用計時器：僅在觸發時送出（事件計時器 = 0）</translation>
    </message>
    <message>
        <source>Empty the list of mapped objects so it may be rewritten (mapping sub-index 0 = 0)</source>
        <translation>清空映射物件清單以便重新寫入（映射子索引 0 = 0）</translation>
    </message>
    <message>
        <source>Object %1 of the message: %2, %3 bits (mapping entry %4)</source>
        <translation>訊息的第 %1 個物件：%2，%3 位元（映射項目 %4）</translation>
    </message>
    <message>
        <source>Activate the %1 mapped objects (mapping sub-index 0 = number of entries)</source>
        <translation>啟用這 %1 個映射物件（映射子索引 0 = 項目數）</translation>
    </message>
    <message>
        <source>Switch %1 on again with CAN-ID %2h (COB-ID bit 31 = 0)</source>
        <translation>以 CAN-ID %2h 重新開啟 %1（COB-ID 位元 31 = 0）</translation>
    </message>
    <message>
        <source>Map %1 of node %2</source>
        <translation>映射節點 %2 的 %1</translation>
    </message>
    <message>
        <source>node %1 %2: %3; nothing would be sent</source>
        <translation>節點 %1 %2：%3；不會送出任何內容</translation>
    </message>
    <message>
        <source>node %1 %2: %3; nothing was sent</source>
        <translation>節點 %1 %2：%3；未送出任何內容</translation>
    </message>
    <message>
        <source>Stop process data so the PDO can be changed (NMT enter pre-operational, CiA 301 §7.3.2)</source>
        <translation>停止過程資料，以便修改 PDO（NMT 進入預操作狀態，CiA 301 §7.3.2）</translation>
    </message>
    <message>
        <source>Check: the COB-ID reads back as written</source>
        <translation>確認：讀回的 COB-ID 與寫入值相同</translation>
    </message>
    <message>
        <source>Check: the transmission type reads back as written</source>
        <translation>確認：讀回的傳輸類型與寫入值相同</translation>
    </message>
    <message>
        <source>Check: the inhibit time reads back as written</source>
        <translation>確認：讀回的禁止時間與寫入值相同</translation>
    </message>
    <message>
        <source>Check: the event timer reads back as written</source>
        <translation>確認：讀回的事件計時器與寫入值相同</translation>
    </message>
    <message>
        <source>Check: the number of mapped objects reads back as written</source>
        <translation>確認：讀回的映射物件數與寫入值相同</translation>
    </message>
    <message>
        <source>Check: mapping entry %1 reads back as written</source>
        <translation>確認：讀回的映射項目 %1 與寫入值相同</translation>
    </message>
    <message>
        <source>reading the current %1: %2</source>
        <translation>讀取目前的 %1：%2</translation>
    </message>
    <message>
        <source>%1 failed: %2; previous mapping restored</source>
        <translation>%1 失敗：%2；已恢復先前的映射</translation>
    </message>
    <message>
        <source>%1 failed: %2; restoring the previous mapping failed too: %3</source>
        <translation>%1 失敗：%2；恢復先前的映射也失敗：%3</translation>
    </message>
    <message>
        <source>%1 failed: %2</source>
        <translation>%1 失敗：%2</translation>
    </message>
    <message>
        <source>COB-ID invalid</source>
        <translation>COB-ID 設為無效</translation>
    </message>
    <message>
        <source>COB-ID valid</source>
        <translation>COB-ID 設為有效</translation>
    </message>
    <message>
        <source>transmission type</source>
        <translation>傳輸類型</translation>
    </message>
    <message>
        <source>inhibit time</source>
        <translation>禁止時間</translation>
    </message>
    <message>
        <source>event timer</source>
        <translation>事件計時器</translation>
    </message>
    <message>
        <source>mapping sub0 = 0</source>
        <translation>映射 sub0 = 0</translation>
    </message>
    <message>
        <source>mapping entry %1</source>
        <translation>映射項目 %1</translation>
    </message>
    <message>
        <source>mapping sub0 = %1</source>
        <translation>映射 sub0 = %1</translation>
    </message>
    <message>
        <source>COB-ID reads back as %1</source>
        <translation>讀回的 COB-ID 為 %1</translation>
    </message>
    <message>
        <source>transmission type reads back as %1</source>
        <translation>讀回的傳輸類型為 %1</translation>
    </message>
    <message>
        <source>the mapping reads back differently (%1 entries)</source>
        <translation>讀回的映射不同（%1 個項目）</translation>
    </message>
    <message>
        <source>inhibit time reads back differently</source>
        <translation>讀回的禁止時間不同</translation>
    </message>
    <message>
        <source>event timer reads back differently</source>
        <translation>讀回的事件計時器不同</translation>
    </message>
    <message>
        <source>verify</source>
        <translation>驗證</translation>
    </message>
    <message>
        <source>verify: %1</source>
        <translation>驗證：%1</translation>
    </message>
    <message>
        <source>read-back failed: %1</source>
        <translation>讀回失敗：%1</translation>
    </message>
    <message>
        <source>the unconfigured device</source>
        <translation>未設定節點 ID 的裝置</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Reopen the adapter at %1, the device&apos;s new bit rate</source>
        <translation>以裝置的新鮑率 %1 重新開啟轉接器</translation>
    </message>
    <message>
        <source>node-ID %1 is not 1-127</source>
        <translation>節點 ID %1 不在 1–127 之間</translation>
    </message>
    <message>
        <source>the new node-ID must be 1-127</source>
        <translation>新的節點 ID 必須在 1–127 之間</translation>
    </message>
    <message>
        <source>node %1 already has this node-ID</source>
        <translation>節點 %1 已經是這個節點 ID</translation>
    </message>
    <message>
        <source>%1 allows node-IDs %2-%3 only</source>
        <translation>%1 只允許節點 ID %2–%3</translation>
    </message>
    <message>
        <source>Change node-ID %1 → %2</source>
        <translation>變更節點 ID %1 → %2</translation>
    </message>
    <message>
        <source>Pick this one device by its identity so only it listens to the next commands (LSS switch state selective)</source>
        <translation>依識別資料選取這一台裝置，讓接下來的命令只有它接收（LSS 選擇性切換狀態）</translation>
    </message>
    <message>
        <source>Give it node-ID %1; not used yet (LSS configure node-ID)</source>
        <translation>設定節點 ID 為 %1；尚未生效（LSS 設定節點 ID）</translation>
    </message>
    <message>
        <source>Make the device keep the new node-ID after power-off (LSS store configuration)</source>
        <translation>讓裝置在斷電後保留新的節點 ID（LSS 儲存設定）</translation>
    </message>
    <message>
        <source>End the setting mode (LSS switch state global: waiting)</source>
        <translation>結束設定模式（LSS 全域切換狀態：等待）</translation>
    </message>
    <message>
        <source>Restart its communication so it uses node-ID %1 (NMT reset communication)</source>
        <translation>重置它的通訊，使其改用節點 ID %1（NMT 重置通訊）</translation>
    </message>
    <message>
        <source>Wait until it reports at node-ID %1 (boot-up / heartbeat)</source>
        <translation>等待它以節點 ID %1 回報（上線訊息／心跳）</translation>
    </message>
    <message>
        <source>at once when the setting mode ends (the device starts with its new node-ID)</source>
        <translation>設定模式結束時立即生效（裝置以新的節點 ID 啟動）</translation>
    </message>
    <message>
        <source>after NMT reset communication (sent by this wizard) or a power cycle</source>
        <translation>在 NMT 重置通訊（由本精靈送出）或重新上電之後</translation>
    </message>
    <message>
        <source>Look for the device at node-ID %1 (scan). If it is not there: switch it off and on; if it still does not answer, find it with LSS Fastscan / inquiry and set the node-ID again.</source>
        <translation>在節點 ID %1 尋找裝置（掃描）。若找不到：將它斷電再上電；若仍無回應，用 LSS Fastscan／查詢找出它，再重新設定節點 ID。</translation>
    </message>
    <message>
        <source>%1 has no documented node-ID parameter; use LSS</source>
        <translation>%1 沒有文件記載的節點 ID 參數；請使用 LSS</translation>
    </message>
    <message>
        <source>this device</source>
        <translation>此裝置</translation>
    </message>
    <message>
        <source>an LSS-unconfigured device has no node-ID for SDO; use LSS</source>
        <translation>尚未經 LSS 設定的裝置沒有可供 SDO 使用的節點 ID；請使用 LSS</translation>
    </message>
    <message>
        <source>Write the new node-ID %1 into %2 (SDO download)</source>
        <translation>將新的節點 ID %1 寫入 %2（SDO 下載）</translation>
    </message>
    <message>
        <source>Write the new node-ID %1 into %2 [object inferred] (SDO download)</source>
        <translation>將新的節點 ID %1 寫入 %2 [物件為推定]（SDO 下載）</translation>
    </message>
    <message>
        <source>Save the parameters so the node-ID survives power-off (store parameters, 1010h &quot;save&quot;)</source>
        <translation>儲存參數，讓節點 ID 在斷電後仍保留（儲存參數，1010h &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Restart the device so it takes node-ID %1 (NMT reset node)</source>
        <translation>重置裝置，使其採用節點 ID %1（NMT 重置節點）</translation>
    </message>
    <message>
        <source>after a power cycle (%1). The wizard also sends NMT reset node, which many drives accept; if the drive does not come back, switch it off and on while the wizard waits.</source>
        <translation>在重新上電之後（%1）。精靈也會送出 NMT 重置節點，許多驅動器接受此命令；若驅動器沒有回來，請在精靈等待時將它斷電再上電。</translation>
    </message>
    <message>
        <source>after NMT reset node (sent by this wizard) or a power cycle (%1)</source>
        <translation>在 NMT 重置節點（由本精靈送出）或重新上電之後（%1）</translation>
    </message>
    <message>
        <source>Switch the drive off and on and look for it at node-ID %1, then at %2. If it answers at %2, the change is stored; if it answers at %1, write %3 again or use LSS.</source>
        <translation>將驅動器斷電再上電，先在節點 ID %1、再在 %2 尋找它。若在 %2 回應，變更已儲存；若在 %1 回應，請重新寫入 %3 或改用 LSS。</translation>
    </message>
    <message>
        <source>choose the new bit rate</source>
        <translation>請選擇新的鮑率</translation>
    </message>
    <message>
        <source>the bus already runs at %1</source>
        <translation>匯流排已經以 %1 運作</translation>
    </message>
    <message>
        <source>give the device a node-ID first; then change its bit rate</source>
        <translation>請先給裝置節點 ID，再變更它的鮑率</translation>
    </message>
    <message>
        <source>Change bit rate of node %1: %2 → %3</source>
        <translation>變更節點 %1 的鮑率：%2 → %3</translation>
    </message>
    <message>
        <source>Find node %1 at %2</source>
        <translation>以 %2 尋找節點 %1</translation>
    </message>
    <message>
        <source>%1 is not in the LSS bit-rate table (CiA 305 Table 1)</source>
        <translation>%1 不在 LSS 鮑率表中（CiA 305 表 1）</translation>
    </message>
    <message>
        <source>Pick this one device by its identity so only it listens (LSS switch state selective)</source>
        <translation>依識別資料選取這一台裝置，讓只有它接收（LSS 選擇性切換狀態）</translation>
    </message>
    <message>
        <source>Give it the new bit rate %1; not used yet (LSS configure bit timing)</source>
        <translation>設定新鮑率 %1；尚未生效（LSS 設定位元時序）</translation>
    </message>
    <message>
        <source>Make it keep the new bit rate after power-off (LSS store configuration)</source>
        <translation>讓它在斷電後保留新鮑率（LSS 儲存設定）</translation>
    </message>
    <message>
        <source>Switch to the new bit rate now; it goes silent on this bus (LSS activate bit timing)</source>
        <translation>立即切換到新鮑率；它在這條匯流排上將不再出聲（LSS 啟用位元時序）</translation>
    </message>
    <message>
        <source>at once with LSS activate bit timing (and at every power-on after the store)</source>
        <translation>在 LSS 啟用位元時序時立即生效（儲存後每次上電亦然）</translation>
    </message>
    <message>
        <source>%1 has no documented bit-rate parameter; use LSS</source>
        <translation>%1 沒有文件記載的鮑率參數；請使用 LSS</translation>
    </message>
    <message>
        <source>%1 cannot be set to %2</source>
        <translation>%1 無法設為 %2</translation>
    </message>
    <message>
        <source>Write %1 = %2h: bit rate %3 (SDO download)</source>
        <translation>寫入 %1 = %2h：鮑率 %3（SDO 下載）</translation>
    </message>
    <message>
        <source>Save the parameters (store parameters, 1010h &quot;save&quot;)</source>
        <translation>儲存參數（儲存參數，1010h &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Restart the device so it runs at %1; it goes silent on this bus (NMT reset node)</source>
        <translation>重置裝置，使其以 %1 運作；它在這條匯流排上將不再出聲（NMT 重置節點）</translation>
    </message>
    <message>
        <source>Let the reset leave the adapter and the device restart before reconnecting</source>
        <translation>重新連線前，先讓重置命令送出、裝置完成重新啟動</translation>
    </message>
    <message>
        <source>after a power cycle (%1); the wizard also sends NMT reset node</source>
        <translation>在重新上電之後（%1）；精靈也會送出 NMT 重置節點</translation>
    </message>
    <message>
        <source>after NMT reset node (%1)</source>
        <translation>在 NMT 重置節點之後（%1）</translation>
    </message>
    <message>
        <source>Ask it to announce itself at the new bit rate (NMT reset communication)</source>
        <translation>請它以新鮑率重新報到（NMT 重置通訊）</translation>
    </message>
    <message>
        <source>Wait until node %1 reports at %2 (boot-up / heartbeat)</source>
        <translation>等待節點 %1 以 %2 回報（上線訊息／心跳）</translation>
    </message>
    <message>
        <source>Reconnect at %1 (the old rate) and scan: if node %2 is there, the change did not take effect — switch it off and on and try again at %3. If it answers at neither rate, try the other standard rates, or use LSS with this device alone on the bus.</source>
        <translation>以 %1（舊鮑率）重新連線並掃描：若節點 %2 仍在，表示變更未生效——將它斷電再上電，再以 %3 嘗試。若兩種鮑率都沒有回應，請試試其他標準鮑率，或讓匯流排上只剩這台裝置再使用 LSS。</translation>
    </message>
    <message>
        <source>cannot read the bit-rate parameter: %1</source>
        <translation>無法讀取鮑率參數：%1</translation>
    </message>
    <message>
        <source>cannot read the identity (1018h) that LSS needs to pick this device: %1</source>
        <translation>無法讀取 LSS 選取此裝置所需的識別資料（1018h）：%1</translation>
    </message>
    <message>
        <source>Put back what was changed</source>
        <translation>恢復已變更的設定</translation>
    </message>
    <message>
        <source>Put the old node-ID %1 back (LSS configure node-ID)</source>
        <translation>恢復舊的節點 ID %1（LSS 設定節點 ID）</translation>
    </message>
    <message>
        <source>Put the old bit rate %1 back (LSS configure bit timing)</source>
        <translation>恢復舊鮑率 %1（LSS 設定位元時序）</translation>
    </message>
    <message>
        <source>Store the old setting again (LSS store configuration)</source>
        <translation>再次儲存舊設定（LSS 儲存設定）</translation>
    </message>
    <message>
        <source>Write the old value back</source>
        <translation>寫回舊值</translation>
    </message>
    <message>
        <source>Save the old value again</source>
        <translation>再次儲存舊值</translation>
    </message>
    <message>
        <source>step %1: %2</source>
        <translation>第 %1 步：%2</translation>
    </message>
    <message>
        <source>No device answered LSS with this identity. Check that the drive supports LSS (CiA 305); if not, use its own parameter (vendor method) or the vendor&apos;s tool.</source>
        <translation>沒有裝置以此識別資料回應 LSS。請確認驅動器支援 LSS（CiA 305）；若不支援，請改用它自己的參數（廠商方式）或廠商的工具。</translation>
    </message>
    <message>
        <source>The device refused the value. Check that it supports it (its manual&apos;s node-ID range / bit rates).</source>
        <translation>裝置拒絕了這個值。請確認它支援此值（見手冊的節點 ID 範圍／鮑率）。</translation>
    </message>
    <message>
        <source>The device could not save the setting, so it would be lost at power-off. Check that it supports LSS store (some keep the setting only until power-off); try its own parameter instead.</source>
        <translation>裝置無法儲存設定，斷電後設定會遺失。請確認它支援 LSS 儲存（有些裝置只保留到斷電為止）；請改用它自己的參數。</translation>
    </message>
    <message>
        <source>Check that %1 is powered and answers at this node-ID, that the parameter can be written now (some drives refuse parameter writes while the servo is on or in another control mode) and that the value is in range.</source>
        <translation>請確認%1已上電並以此節點 ID 回應、此時參數可以寫入（有些驅動器在伺服啟動中或其他控制模式下會拒絕寫入參數），且數值在範圍內。</translation>
    </message>
    <message>
        <source>Check the connection to %1 and try again.</source>
        <translation>請檢查與%1的連線後再試一次。</translation>
    </message>
    <message>
        <source>Put back: %1.</source>
        <translation>已恢復：%1。</translation>
    </message>
    <message>
        <source>Could not put everything back (%1: %2).</source>
        <translation>無法全部恢復（%1：%2）。</translation>
    </message>
    <message>
        <source>Delta ASDA-A2 manual §1.3.1, P3-00 (&quot;●&quot;: after power cycle)</source>
        <translation>Delta ASDA-A2 手冊 §1.3.1，P3-00（「●」：重新上電後生效）</translation>
    </message>
    <message>
        <source>Delta ASDA-A2 manual §1.3.1, P3-01 digit Z</source>
        <translation>Delta ASDA-A2 手冊 §1.3.1，P3-01 第 Z 位</translation>
    </message>
    <message>
        <source>AIMOTOR manual, CAN settings (H0C-00; object 200Ch:01 inferred)</source>
        <translation>AIMOTOR 手冊，CAN 設定（H0C-00；物件 200Ch:01 為推定）</translation>
    </message>
    <message>
        <source>DEXMART DEV tutorial §8.7 (parameter 09-19, DEV Rev A only)</source>
        <translation>DEXMART DEV 教學 §8.7（參數 09-19，僅限 DEV Rev A）</translation>
    </message>
    <message>
        <source>node %1 axis %2</source>
        <translation>節點 %1 軸 %2</translation>
    </message>
    <message>
        <source>%1 went to %2 instead of %3: statusword 0x%4</source>
        <translation>%1 進入了%2，而不是%3：狀態字 0x%4</translation>
    </message>
    <message>
        <source>%1 did not reach %2 within %3 ms: statusword 0x%4 (%5): %6</source>
        <translation>%1 未在 %3 ms 內到達%2：狀態字 0x%4（%5）：%6</translation>
    </message>
    <message>
        <source>missing bit %1 (%2)</source>
        <translation>缺少位元 %1（%2）</translation>
    </message>
    <message>
        <source>unexpected bit %1 (%2)</source>
        <translation>多出位元 %1（%2）</translation>
    </message>
    <message>
        <source>%1 (bit %2) is on: %3</source>
        <translation>%1（位元 %2）為 on：%3</translation>
    </message>
    <message>
        <source>%1 (bit %2) is off: %3</source>
        <translation>%1（位元 %2）為 off：%3</translation>
    </message>
    <message>
        <source>%1 (bit %2) is on</source>
        <translation>%1（位元 %2）為 on</translation>
    </message>
    <message>
        <source>%1 (bit %2) is off</source>
        <translation>%1（位元 %2）為 off</translation>
    </message>
    <message>
        <source>bit 7 low before fault reset</source>
        <translation>故障重置前將位元 7 設為低</translation>
    </message>
    <message>
        <source>Disable voltage, enable failed</source>
        <translation>切斷電壓（致能失敗）</translation>
    </message>
    <message>
        <source>%1; drive disabled</source>
        <translation>%1；已解除驅動器致能</translation>
    </message>
    <message>
        <source>%1; disabling the drive failed too: %2</source>
        <translation>%1；解除驅動器致能也失敗：%2</translation>
    </message>
    <message>
        <source>%1: modes of operation display %2h shows %3 (%4), not %5 (%6), after %7 ms</source>
        <translation>%1：%7 ms 後，操作模式顯示 %2h 為 %3（%4），而不是 %5（%6）</translation>
    </message>
    <message>
        <source>Controlword bit 7 low first: fault reset acts on its rising edge</source>
        <translation>先將控制字位元 7 設為低：故障重置在上升緣動作</translation>
    </message>
    <message>
        <source>Clear the fault (Fault reset, CiA 402 transition 15)</source>
        <translation>清除故障（故障重置，CiA 402 轉換 15）</translation>
    </message>
    <message>
        <source>Make the drive ready (Shutdown, transition 2)</source>
        <translation>讓驅動器就緒（Shutdown，轉換 2）</translation>
    </message>
    <message>
        <source>Switch the power stage on, motor not yet energised (Switch on, transition 3)</source>
        <translation>開啟功率級，馬達尚未通電（Switch on，轉換 3）</translation>
    </message>
    <message>
        <source>Energise the motor: it holds position and follows commands (Enable operation, transition 4)</source>
        <translation>馬達通電：保持位置並跟隨命令（運轉致能，轉換 4）</translation>
    </message>
    <message>
        <source>Stop following commands, power stage stays on (Disable operation, transition 5)</source>
        <translation>停止跟隨命令，功率級保持開啟（Disable operation，轉換 5）</translation>
    </message>
    <message>
        <source>Remove power from the motor (Disable voltage)</source>
        <translation>切斷馬達電源（Disable voltage）</translation>
    </message>
    <message>
        <source>Brake on the quick stop ramp (Quick stop)</source>
        <translation>依快速停止斜坡減速（Quick stop）</translation>
    </message>
    <message>
        <source>Statusword must show %1</source>
        <translation>狀態字必須顯示%1</translation>
    </message>
    <message>
        <source>CiA 402 enable of node %1</source>
        <translation>節點 %1 的 CiA 402 致能</translation>
    </message>
    <message>
        <source>CiA 402 enable of node %1 axis %2</source>
        <translation>節點 %1 軸 %2 的 CiA 402 致能</translation>
    </message>
    <message>
        <source>Choose the mode of operation: %1 (6060h)</source>
        <translation>選擇操作模式：%1（6060h）</translation>
    </message>
    <message>
        <source>The drive confirms the mode (modes of operation display 6061h)</source>
        <translation>驅動器確認模式（操作模式顯示 6061h）</translation>
    </message>
    <message>
        <source>jog velocity must be non-zero and at most %1 units/s</source>
        <translation>寸動速度不可為 0，且最多 %1 單位/s</translation>
    </message>
    <message>
        <source>profile velocity must be 1-%1 units/s</source>
        <translation>輪廓速度必須在 1–%1 單位/s 之間</translation>
    </message>
    <message>
        <source>relative move must be non-zero and at most %1 units</source>
        <translation>相對移動量不可為 0，且最多 %1 單位</translation>
    </message>
    <message>
        <source>acceleration and deceleration must be above 0</source>
        <translation>加速度與減速度必須大於 0</translation>
    </message>
    <message>
        <source>test move time must be 1-%1 ms</source>
        <translation>測試運動時間必須在 1–%1 ms 之間</translation>
    </message>
    <message>
        <source>watchdog must be at least 50 ms</source>
        <translation>看門狗時間至少須 50 ms</translation>
    </message>
    <message>
        <source>a test move is already running</source>
        <translation>已有測試運動在執行中</translation>
    </message>
    <message>
        <source>%1 (profile acceleration)</source>
        <translation>%1（輪廓加速度）</translation>
    </message>
    <message>
        <source>%1 (profile deceleration)</source>
        <translation>%1（輪廓減速度）</translation>
    </message>
    <message>
        <source>Enable operation, halt off</source>
        <translation>運轉致能，解除暫停（halt）</translation>
    </message>
    <message>
        <source>%1 (target velocity)</source>
        <translation>%1（目標速度）</translation>
    </message>
    <message>
        <source>%1 (profile velocity)</source>
        <translation>%1（輪廓速度）</translation>
    </message>
    <message>
        <source>%1 (target position, relative)</source>
        <translation>%1（目標位置，相對）</translation>
    </message>
    <message>
        <source>Enable operation, relative, new set-point low</source>
        <translation>運轉致能，相對，新設定點為低</translation>
    </message>
    <message>
        <source>New set-point (bit 4 rising), relative (bit 6)</source>
        <translation>新設定點（位元 4 上升緣），相對（位元 6）</translation>
    </message>
    <message>
        <source>test move set-up failed: %1</source>
        <translation>測試運動設定失敗：%1</translation>
    </message>
    <message>
        <source>%1 is in %2, not Operation enabled: enable the drive before a test move</source>
        <translation>%1 處於%2，不是運轉致能：測試運動前請先致能驅動器</translation>
    </message>
    <message>
        <source>cannot set the mode for the test move: %1</source>
        <translation>無法設定測試運動的模式：%1</translation>
    </message>
    <message>
        <source>the drive stopped answering during the test move (%1)</source>
        <translation>測試運動中驅動器停止回應（%1）</translation>
    </message>
    <message>
        <source>the drive faulted during the test move (statusword 0x%1)</source>
        <translation>測試運動中驅動器發生故障（狀態字 0x%1）</translation>
    </message>
    <message>
        <source>the drive left Operation enabled during the test move (now %1)</source>
        <translation>測試運動中驅動器離開了運轉致能（現在為%1）</translation>
    </message>
    <message>
        <source>position read failed during the test move: %1</source>
        <translation>測試運動中讀取位置失敗：%1</translation>
    </message>
    <message>
        <source>velocity read failed during the test move: %1</source>
        <translation>測試運動中讀取速度失敗：%1</translation>
    </message>
    <message>
        <source>hold-to-run released (no signal for %1 ms)</source>
        <translation>已放開按住運轉（%1 ms 沒有訊號）</translation>
    </message>
    <message>
        <source>time limit of %1 ms reached</source>
        <translation>已達 %1 ms 的時間上限</translation>
    </message>
    <message>
        <source>Halt: stop the test move on the deceleration ramp</source>
        <translation>暫停（Halt）：依減速斜坡停止測試運動</translation>
    </message>
    <message>
        <source>halt failed: %1</source>
        <translation>暫停失敗：%1</translation>
    </message>
    <message>
        <source>velocity read failed while stopping: %1</source>
        <translation>停止時讀取速度失敗：%1</translation>
    </message>
    <message>
        <source>the motor did not stop within %1 ms of the halt</source>
        <translation>暫停後 %1 ms 內馬達未停止</translation>
    </message>
    <message>
        <source>%1: %2h = 0 (target velocity)</source>
        <translation>%1：%2h = 0（目標速度）</translation>
    </message>
    <message>
        <source>target velocity 0 failed: %1</source>
        <translation>目標速度設為 0 失敗：%1</translation>
    </message>
    <message>
        <source>Quick stop, test move failed</source>
        <translation>快速停止（測試運動失敗）</translation>
    </message>
    <message>
        <source>Disable voltage, test move failed</source>
        <translation>切斷電壓（測試運動失敗）</translation>
    </message>
    <message>
        <source>node-ID %1 is outside 1-127</source>
        <translation>節點 ID %1 不在 1–127 之間</translation>
    </message>
    <message>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <source>node %1 read %2: cancelled</source>
        <translation>節點 %1 讀取 %2：已取消</translation>
    </message>
    <message>
        <source>node %1 write %2: cancelled</source>
        <translation>節點 %1 寫入 %2：已取消</translation>
    </message>
    <message>
        <source>the server answered for %1</source>
        <translation>伺服端回應的是 %1</translation>
    </message>
    <message>
        <source>toggle bit not alternated in an upload segment</source>
        <translation>上傳分段的切換位元沒有交替</translation>
    </message>
    <message>
        <source>the server sent %1 bytes, more than the %2 it announced</source>
        <translation>伺服端送出 %1 位元組，多於宣告的 %2</translation>
    </message>
    <message>
        <source>the server sent %1 bytes of the %2 it announced</source>
        <translation>伺服端只送出宣告 %2 位元組中的 %1</translation>
    </message>
    <message>
        <source>toggle bit not alternated in a download segment response</source>
        <translation>下載分段回應的切換位元沒有交替</translation>
    </message>
    <message>
        <source>unexpected %1 from the server</source>
        <translation>伺服端送來非預期的 %1</translation>
    </message>
    <message>
        <source>block end says %1 unused bytes</source>
        <translation>區塊結束標示 %1 個未使用位元組</translation>
    </message>
    <message>
        <source>CRC error: the server sent %1, the data gives %2</source>
        <translation>CRC 錯誤：伺服端送出 %1，資料計算為 %2</translation>
    </message>
    <message>
        <source>invalid block size %1</source>
        <translation>無效的區塊大小 %1</translation>
    </message>
    <message>
        <source>acknowledged segment %1 of %2 sent</source>
        <translation>已確認 %2 個已送出分段中的第 %1 個</translation>
    </message>
    <message>
        <source>node %1 did not answer read of %2 within %3 ms (SDO protocol timed out, 0x05040000)</source>
        <translation>節點 %1 未在 %3 ms 內回應 %2 的讀取（SDO 協定逾時，0x05040000）</translation>
    </message>
    <message>
        <source>node %1 did not answer write of %2 within %3 ms (SDO protocol timed out, 0x05040000)</source>
        <translation>節點 %1 未在 %3 ms 內回應 %2 的寫入（SDO 協定逾時，0x05040000）</translation>
    </message>
    <message>
        <source>node %1 aborted %2: %3</source>
        <translation>節點 %1 中止了 %2：%3</translation>
    </message>
    <message>
        <source>node %1 read %2: %3; transfer aborted with 0x%4</source>
        <translation>節點 %1 讀取 %2：%3；傳輸以 0x%4 中止</translation>
    </message>
    <message>
        <source>node %1 write %2: %3; transfer aborted with 0x%4</source>
        <translation>節點 %1 寫入 %2：%3；傳輸以 0x%4 中止</translation>
    </message>
    <message>
        <source>node %1 read %2: %3</source>
        <translation>節點 %1 讀取 %2：%3</translation>
    </message>
    <message>
        <source>node %1 write %2: %3</source>
        <translation>節點 %1 寫入 %2：%3</translation>
    </message>
    <message>
        <source>not supported or out of range</source>
        <translation>不支援或超出範圍</translation>
    </message>
    <message>
        <source>manufacturer-specific error</source>
        <translation>製造商自訂錯誤</translation>
    </message>
    <message>
        <source>error %1</source>
        <translation>錯誤 %1</translation>
    </message>
    <message>
        <source>LSS %1 refused by the slave: %2 (error code %3)</source>
        <translation>從站拒絕 LSS %1：%2（錯誤碼 %3）</translation>
    </message>
    <message>
        <source>no slave with that identity answered switch state selective</source>
        <translation>沒有符合此識別資料的從站回應選擇性切換狀態</translation>
    </message>
    <message>
        <source>no answer to LSS configure node-ID (is a slave in configuration state?)</source>
        <translation>LSS 設定節點 ID 沒有回應（是否有從站處於設定狀態？）</translation>
    </message>
    <message>
        <source>configure node-ID</source>
        <translation>設定節點 ID</translation>
    </message>
    <message>
        <source>%1 bit/s is not in the CiA 305 bit timing table</source>
        <translation>%1 bit/s 不在 CiA 305 位元時序表中</translation>
    </message>
    <message>
        <source>no answer to LSS configure bit timing (is a slave in configuration state?)</source>
        <translation>LSS 設定位元時序沒有回應（是否有從站處於設定狀態？）</translation>
    </message>
    <message>
        <source>configure bit timing</source>
        <translation>設定位元時序</translation>
    </message>
    <message>
        <source>no answer to LSS store configuration (is a slave in configuration state?)</source>
        <translation>LSS 儲存設定沒有回應（是否有從站處於設定狀態？）</translation>
    </message>
    <message>
        <source>store configuration</source>
        <translation>儲存設定</translation>
    </message>
    <message>
        <source>no answer to LSS %1 (is a slave in configuration state?)</source>
        <translation>LSS %1 沒有回應（是否有從站處於設定狀態？）</translation>
    </message>
    <message>
        <source>this run cannot reopen the adapter; reconnect at %1 bit/s by hand</source>
        <translation>此次執行無法重新開啟轉接器；請手動以 %1 bit/s 重新連線</translation>
    </message>
    <message>
        <source>could not reopen the adapter</source>
        <translation>無法重新開啟轉接器</translation>
    </message>
    <message>
        <source>connected at %1 bit/s</source>
        <translation>已以 %1 bit/s 連線</translation>
    </message>
    <message>
        <source>step %1 (%2): cancelled</source>
        <translation>第 %1 步（%2）：已取消</translation>
    </message>
    <message>
        <source>step %1 (%2): %3</source>
        <translation>第 %1 步（%2）：%3</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <source>read %1</source>
        <translation>讀到 %1</translation>
    </message>
    <message>
        <source>read %1 as expected</source>
        <translation>讀到 %1，符合預期</translation>
    </message>
    <message>
        <source>node %1 %2 reads %3, expected %4</source>
        <translation>節點 %1 %2 讀到 %3，預期為 %4</translation>
    </message>
    <message>
        <source>node %1 %2 reads %3, expected %4 under mask %5</source>
        <translation>節點 %1 %2 讀到 %3，預期為 %4（遮罩 %5）</translation>
    </message>
    <message>
        <source>sent</source>
        <translation>已送出</translation>
    </message>
    <message>
        <source>the device confirmed</source>
        <translation>裝置已確認</translation>
    </message>
    <message>
        <source>the device stored it</source>
        <translation>裝置已儲存</translation>
    </message>
    <message>
        <source>waited %1 ms</source>
        <translation>已等待 %1 ms</translation>
    </message>
    <message>
        <source>node %1 sent no boot-up within %2 ms</source>
        <translation>節點 %1 未在 %2 ms 內送出上線訊息</translation>
    </message>
    <message>
        <source>node %1 sent no boot-up or heartbeat within %2 ms</source>
        <translation>節點 %1 未在 %2 ms 內送出上線訊息或心跳</translation>
    </message>
    <message>
        <source>unknown step</source>
        <translation>未知的步驟</translation>
    </message>
    <message>
        <source>node %1 booted</source>
        <translation>節點 %1 已上線</translation>
    </message>
    <message>
        <source>node %1 is %2</source>
        <translation>節點 %1 為%2</translation>
    </message>
    <message>
        <source>node-ID %1 is outside 1-127 (0 = all nodes)</source>
        <translation>節點 ID %1 不在 1–127 之間（0 = 所有節點）</translation>
    </message>
    <message>
        <source>%1 (not writable)</source>
        <translation>%1（不可寫入）</translation>
    </message>
    <message>
        <source>command object, not configuration</source>
        <translation>命令物件，不是設定值</translation>
    </message>
    <message>
        <source>unchanged (%1)</source>
        <translation>未變更（%1）</translation>
    </message>
    <message>
        <source>node %1 %2: not in the dictionary</source>
        <translation>節點 %1 %2：不在物件字典中</translation>
    </message>
    <message>
        <source>COB-ID invalid (%1)</source>
        <translation>COB-ID 設為無效（%1）</translation>
    </message>
    <message>
        <source>COB-ID valid (%1)</source>
        <translation>COB-ID 設為有效（%1）</translation>
    </message>
    <message>
        <source>transmission type (%1)</source>
        <translation>傳輸類型（%1）</translation>
    </message>
    <message>
        <source>inhibit time (%1)</source>
        <translation>禁止時間（%1）</translation>
    </message>
    <message>
        <source>event timer (%1)</source>
        <translation>事件計時器（%1）</translation>
    </message>
    <message>
        <source>mapping sub0 = 0 (%1)</source>
        <translation>映射 sub0 = 0（%1）</translation>
    </message>
    <message>
        <source>mapping entry %1 (%2)</source>
        <translation>映射項目 %1（%2）</translation>
    </message>
    <message>
        <source>Error reset or no error</source>
        <translation>錯誤重置或無錯誤</translation>
    </message>
    <message>
        <source>Generic error</source>
        <translation>一般錯誤</translation>
    </message>
    <message>
        <source>Continuous over-current</source>
        <translation>持續過電流</translation>
    </message>
    <message>
        <source>Short circuit / earth leakage</source>
        <translation>短路／接地漏電</translation>
    </message>
    <message>
        <source>Mains over-voltage</source>
        <translation>主電源過電壓</translation>
    </message>
    <message>
        <source>Mains under-voltage</source>
        <translation>主電源欠電壓</translation>
    </message>
    <message>
        <source>DC link over-voltage</source>
        <translation>直流母線過電壓</translation>
    </message>
    <message>
        <source>DC link under-voltage</source>
        <translation>直流母線欠電壓</translation>
    </message>
    <message>
        <source>Excess temperature device</source>
        <translation>裝置溫度過高</translation>
    </message>
    <message>
        <source>Excess temperature drive</source>
        <translation>驅動器溫度過高</translation>
    </message>
    <message>
        <source>Data storage error (EEPROM)</source>
        <translation>資料儲存錯誤（EEPROM）</translation>
    </message>
    <message>
        <source>Internal software error</source>
        <translation>內部軟體錯誤</translation>
    </message>
    <message>
        <source>Motor blocked</source>
        <translation>馬達堵轉</translation>
    </message>
    <message>
        <source>Incremental sensor 1 fault</source>
        <translation>增量式感測器 1 故障</translation>
    </message>
    <message>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN 溢位（物件遺失）</translation>
    </message>
    <message>
        <source>CAN in error passive mode</source>
        <translation>CAN 處於錯誤被動模式</translation>
    </message>
    <message>
        <source>Life guard error or heartbeat error</source>
        <translation>節點保護錯誤或心跳錯誤</translation>
    </message>
    <message>
        <source>Recovered from bus off</source>
        <translation>已從匯流排關閉恢復</translation>
    </message>
    <message>
        <source>CAN-ID collision</source>
        <translation>CAN-ID 衝突</translation>
    </message>
    <message>
        <source>PDO not processed due to length error</source>
        <translation>PDO 因長度錯誤未處理</translation>
    </message>
    <message>
        <source>PDO length exceeded</source>
        <translation>PDO 長度超出</translation>
    </message>
    <message>
        <source>DAM MPDO not processed, destination object not available</source>
        <translation>DAM MPDO 未處理，目標物件不存在</translation>
    </message>
    <message>
        <source>Unexpected SYNC data length</source>
        <translation>SYNC 資料長度不符</translation>
    </message>
    <message>
        <source>RPDO timeout</source>
        <translation>RPDO 逾時</translation>
    </message>
    <message>
        <source>Following error</source>
        <translation>追隨誤差</translation>
    </message>
    <message>
        <source>Reference limit</source>
        <translation>參考極限</translation>
    </message>
    <message>
        <source>Current</source>
        <translation>電流</translation>
    </message>
    <message>
        <source>Current, device input side</source>
        <translation>電流（裝置輸入側）</translation>
    </message>
    <message>
        <source>Current inside the device</source>
        <translation>裝置內部電流</translation>
    </message>
    <message>
        <source>Current, device output side</source>
        <translation>電流（裝置輸出側）</translation>
    </message>
    <message>
        <source>Voltage</source>
        <translation>電壓</translation>
    </message>
    <message>
        <source>Mains voltage</source>
        <translation>主電源電壓</translation>
    </message>
    <message>
        <source>Voltage inside the device</source>
        <translation>裝置內部電壓</translation>
    </message>
    <message>
        <source>Output voltage</source>
        <translation>輸出電壓</translation>
    </message>
    <message>
        <source>Temperature</source>
        <translation>溫度</translation>
    </message>
    <message>
        <source>Ambient temperature</source>
        <translation>環境溫度</translation>
    </message>
    <message>
        <source>Device temperature</source>
        <translation>裝置溫度</translation>
    </message>
    <message>
        <source>Device hardware</source>
        <translation>裝置硬體</translation>
    </message>
    <message>
        <source>Device software</source>
        <translation>裝置軟體</translation>
    </message>
    <message>
        <source>Internal software</source>
        <translation>內部軟體</translation>
    </message>
    <message>
        <source>User software</source>
        <translation>使用者軟體</translation>
    </message>
    <message>
        <source>Data set</source>
        <translation>資料集</translation>
    </message>
    <message>
        <source>Additional modules</source>
        <translation>附加模組</translation>
    </message>
    <message>
        <source>Monitoring</source>
        <translation>監控</translation>
    </message>
    <message>
        <source>Communication</source>
        <translation>通訊</translation>
    </message>
    <message>
        <source>Protocol error</source>
        <translation>協定錯誤</translation>
    </message>
    <message>
        <source>External error</source>
        <translation>外部錯誤</translation>
    </message>
    <message>
        <source>Additional functions</source>
        <translation>附加功能</translation>
    </message>
    <message>
        <source>Device specific</source>
        <translation>裝置自訂</translation>
    </message>
    <message>
        <source>Unknown error code</source>
        <translation>未知的錯誤碼</translation>
    </message>
    <message>
        <source>Delta: P-parameters written over CAN are saved to EEPROM at once. P3-00 takes effect after a power cycle (marked ●).</source>
        <translation>台達：經 CAN 寫入的 P 參數會立即存入 EEPROM。P3-00 須重新上電後才生效（標記 ●）。</translation>
    </message>
    <message>
        <source>AIMOTOR: the manual sets H0C-00 (node-ID) with the RS485 tool; writing it over CAN (200Ch:01) is inferred, save with 1010h and power-cycle. The bit-rate codes of H0C-08 are not documented: use LSS for the bit rate.</source>
        <translation>AIMOTOR：手冊以 RS485 工具設定 H0C-00（節點 ID）；經 CAN（200Ch:01）寫入是推定的做法，請以 1010h 儲存並重新上電。H0C-08 的鮑率代碼未見於文件：鮑率請使用 LSS 設定。</translation>
    </message>
    <message>
        <source>DEXMART DEV: parameter 09-19 sets the node-ID on Rev A only; Rev B/C/D use DIP switch SW2. No bit-rate parameter: use LSS.</source>
        <translation>DEXMART DEV：參數 09-19 僅在 Rev A 上設定節點 ID；Rev B/C/D 使用 DIP 開關 SW2。沒有鮑率參數：請使用 LSS。</translation>
    </message>
    <message>
        <source>Voltage enabled</source>
        <translation>電壓已致能</translation>
    </message>
    <message>
        <source>Remote</source>
        <translation>遠端控制（Remote）</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Target reached</source>
        <translation>已到達目標</translation>
    </message>
    <message>
        <source>Internal limit active</source>
        <translation>內部限制作用中</translation>
    </message>
    <message>
        <source>TPDO%1 node %2: %3</source>
        <translation>TPDO%1 節點 %2：%3</translation>
    </message>
    <message>
        <source>RPDO%1 node %2: %3</source>
        <translation>RPDO%1 節點 %2：%3</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Command specifier</source>
        <translation>命令識別碼</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Sub-index</source>
        <translation>子索引</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Data (mapping not known)</source>
        <translation>資料（映射未知）</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止碼</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <source>0 (all nodes)</source>
        <translation>0（所有節點）</translation>
    </message>
    <message>
        <source>Counter</source>
        <translation>計數器</translation>
    </message>
    <message>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <source>Toggle bit</source>
        <translation>切換位元</translation>
    </message>
    <message>
        <source>Error code</source>
        <translation>錯誤碼</translation>
    </message>
    <message>
        <source>Error register</source>
        <translation>錯誤暫存器</translation>
    </message>
    <message>
        <source>Manufacturer-specific error field</source>
        <translation>製造商定義錯誤欄位</translation>
    </message>
    <message>
        <source>Vendor alarm</source>
        <translation>廠商異警</translation>
    </message>
    <message>
        <source>Milliseconds after midnight</source>
        <translation>午夜起的毫秒數</translation>
    </message>
    <message>
        <source>Days since 1984-01-01</source>
        <translation>自 1984-01-01 起的天數</translation>
    </message>
    <message>
        <source>Command (CiA 402)</source>
        <translation>命令（CiA 402）</translation>
    </message>
    <message>
        <source>State (CiA 402)</source>
        <translation>狀態（CiA 402）</translation>
    </message>
    <message>
        <source>Mode of operation (CiA 402)</source>
        <translation>操作模式（CiA 402）</translation>
    </message>
    <message>
        <source>Bit %1</source>
        <translation>位元 %1</translation>
    </message>
    <message>
        <source>set</source>
        <translation>為 1</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>aborted</source>
        <translation>已中止</translation>
    </message>
    <message>
        <source>size mismatch</source>
        <translation>大小不符</translation>
    </message>
    <message>
        <source>crc error</source>
        <translation>CRC 錯誤</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <source>Manufacturer-specific mode %1</source>
        <translation>製造商定義模式 %1</translation>
    </message>
    <message>
        <source>Reserved mode %1</source>
        <translation>保留模式 %1</translation>
    </message>
    <message>
        <source>abort</source>
        <translation>中止</translation>
    </message>
    <message>
        <source>0x%1 %2</source>
        <translation>0x%1 %2</translation>
    </message>
    <message>
        <source>SDO %1 node %2</source>
        <translation>SDO %1 節點 %2</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3</source>
        <translation>SDO %1 節點 %2 %3</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, block size %4</source>
        <translation>SDO %1 節點 %2 %3，區塊大小 %4</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, %4 bytes</source>
        <translation>SDO %1 節點 %2 %3，%4 位元組</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3, block size %4, %5 bytes</source>
        <translation>SDO %1 節點 %2 %3，區塊大小 %4，%5 位元組</translation>
    </message>
    <message>
        <source>%1 [%2]</source>
        <translation>%1［%2］</translation>
    </message>
    <message>
        <source>%1 -&gt; read %2 bytes = %3</source>
        <translation>%1 → 已讀取 %2 位元組 = %3</translation>
    </message>
    <message>
        <source>%1 -&gt; read %2 bytes</source>
        <translation>%1 → 已讀取 %2 位元組</translation>
    </message>
    <message>
        <source>%1 -&gt; wrote %2 bytes = %3</source>
        <translation>%1 → 已寫入 %2 位元組 = %3</translation>
    </message>
    <message>
        <source>%1 -&gt; wrote %2 bytes</source>
        <translation>%1 → 已寫入 %2 位元組</translation>
    </message>
    <message>
        <source>CAN error: %1</source>
        <translation>CAN 錯誤：%1</translation>
    </message>
    <message>
        <source>Error classes</source>
        <translation>錯誤類別</translation>
    </message>
    <message>
        <source>Bus state</source>
        <translation>匯流排狀態</translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>問題</translation>
    </message>
    <message>
        <source>TX error counter</source>
        <translation>傳送錯誤計數器</translation>
    </message>
    <message>
        <source>RX error counter</source>
        <translation>接收錯誤計數器</translation>
    </message>
    <message>
        <source>error active</source>
        <translation>錯誤主動</translation>
    </message>
    <message>
        <source>error warning</source>
        <translation>錯誤警告</translation>
    </message>
    <message>
        <source>error passive</source>
        <translation>錯誤被動</translation>
    </message>
    <message>
        <source>bus-off</source>
        <translation>匯流排關閉</translation>
    </message>
    <message>
        <source>bus-off (the controller stopped sending after too many errors)</source>
        <translation>匯流排關閉（錯誤過多，控制器已停止傳送）</translation>
    </message>
    <message>
        <source>controller: %1</source>
        <translation>控制器：%1</translation>
    </message>
    <message>
        <source>TX error passive</source>
        <translation>傳送錯誤被動</translation>
    </message>
    <message>
        <source>RX error passive</source>
        <translation>接收錯誤被動</translation>
    </message>
    <message>
        <source>TX error warning</source>
        <translation>傳送錯誤警告</translation>
    </message>
    <message>
        <source>RX error warning</source>
        <translation>接收錯誤警告</translation>
    </message>
    <message>
        <source>RX buffer overflow (frames lost)</source>
        <translation>接收緩衝區溢位（封包遺失）</translation>
    </message>
    <message>
        <source>TX buffer overflow</source>
        <translation>傳送緩衝區溢位</translation>
    </message>
    <message>
        <source>back to error active</source>
        <translation>回到錯誤主動</translation>
    </message>
    <message>
        <source>unspecified</source>
        <translation>未指明</translation>
    </message>
    <message>
        <source>no acknowledge (no other node on the bus, or a different bit rate)</source>
        <translation>沒有 ACK 應答（匯流排上沒有其他節點，或鮑率不同）</translation>
    </message>
    <message>
        <source>protocol violation</source>
        <translation>協定錯誤</translation>
    </message>
    <message>
        <source>protocol violation: %1</source>
        <translation>協定錯誤：%1</translation>
    </message>
    <message>
        <source>protocol violation: %1 in the %2</source>
        <translation>協定錯誤：%1（位置：%2）</translation>
    </message>
    <message>
        <source>protocol violation in the %1</source>
        <translation>協定錯誤（位置：%1）</translation>
    </message>
    <message>
        <source>bit error</source>
        <translation>位元錯誤</translation>
    </message>
    <message>
        <source>form error</source>
        <translation>格式錯誤</translation>
    </message>
    <message>
        <source>stuff error</source>
        <translation>填充錯誤</translation>
    </message>
    <message>
        <source>could not send a dominant bit</source>
        <translation>無法送出顯性位元</translation>
    </message>
    <message>
        <source>could not send a recessive bit</source>
        <translation>無法送出隱性位元</translation>
    </message>
    <message>
        <source>bus overload</source>
        <translation>匯流排過載</translation>
    </message>
    <message>
        <source>active error flag</source>
        <translation>主動錯誤旗標</translation>
    </message>
    <message>
        <source>while transmitting</source>
        <translation>傳送時</translation>
    </message>
    <message>
        <source>start of frame</source>
        <translation>封包起始（SOF）</translation>
    </message>
    <message>
        <source>identifier bits %1</source>
        <translation>識別碼位元 %1</translation>
    </message>
    <message>
        <source>SRTR bit</source>
        <translation>SRTR 位元</translation>
    </message>
    <message>
        <source>IDE bit</source>
        <translation>IDE 位元</translation>
    </message>
    <message>
        <source>RTR bit</source>
        <translation>RTR 位元</translation>
    </message>
    <message>
        <source>reserved bit %1</source>
        <translation>保留位元 %1</translation>
    </message>
    <message>
        <source>data length code</source>
        <translation>資料長度碼（DLC）</translation>
    </message>
    <message>
        <source>data field</source>
        <translation>資料欄位</translation>
    </message>
    <message>
        <source>CRC sequence</source>
        <translation>CRC 序列</translation>
    </message>
    <message>
        <source>CRC delimiter</source>
        <translation>CRC 分隔位元</translation>
    </message>
    <message>
        <source>ACK slot</source>
        <translation>ACK 槽</translation>
    </message>
    <message>
        <source>ACK delimiter</source>
        <translation>ACK 分隔位元</translation>
    </message>
    <message>
        <source>end of frame</source>
        <translation>封包結尾（EOF）</translation>
    </message>
    <message>
        <source>intermission</source>
        <translation>封包間隔</translation>
    </message>
    <message>
        <source>transceiver problem (status 0x%1)</source>
        <translation>收發器異常（狀態 0x%1）</translation>
    </message>
    <message>
        <source>lost arbitration at bit %1</source>
        <translation>仲裁失敗（第 %1 位元）</translation>
    </message>
    <message>
        <source>lost arbitration</source>
        <translation>仲裁失敗</translation>
    </message>
    <message>
        <source>transmit timeout</source>
        <translation>傳送逾時</translation>
    </message>
    <message>
        <source>bus error</source>
        <translation>匯流排錯誤</translation>
    </message>
    <message>
        <source>controller restarted</source>
        <translation>控制器已重新啟動</translation>
    </message>
    <message>
        <source>error counters TX %1, RX %2</source>
        <translation>錯誤計數器 TX %1，RX %2</translation>
    </message>
    <message>
        <source>error frame (class %1h)</source>
        <translation>錯誤封包（類別 %1h）</translation>
    </message>
    <message>
        <source>Switch state global</source>
        <translation>全域切換狀態</translation>
    </message>
    <message>
        <source>Switch state selective: vendor-ID</source>
        <translation>選擇性切換狀態：廠商 ID</translation>
    </message>
    <message>
        <source>Switch state selective: product code</source>
        <translation>選擇性切換狀態：產品代碼</translation>
    </message>
    <message>
        <source>Switch state selective: revision number</source>
        <translation>選擇性切換狀態：版本號</translation>
    </message>
    <message>
        <source>Switch state selective: serial number</source>
        <translation>選擇性切換狀態：序號</translation>
    </message>
    <message>
        <source>Switch state selective response</source>
        <translation>選擇性切換狀態回應</translation>
    </message>
    <message>
        <source>Configure node-ID</source>
        <translation>設定節點 ID</translation>
    </message>
    <message>
        <source>Configure node-ID response</source>
        <translation>設定節點 ID 回應</translation>
    </message>
    <message>
        <source>Configure bit timing</source>
        <translation>設定位元時序</translation>
    </message>
    <message>
        <source>Configure bit timing response</source>
        <translation>設定位元時序回應</translation>
    </message>
    <message>
        <source>Activate bit timing</source>
        <translation>啟用位元時序</translation>
    </message>
    <message>
        <source>Store configuration</source>
        <translation>儲存設定</translation>
    </message>
    <message>
        <source>Store configuration response</source>
        <translation>儲存設定回應</translation>
    </message>
    <message>
        <source>Inquire vendor-ID</source>
        <translation>查詢廠商 ID</translation>
    </message>
    <message>
        <source>Vendor-ID</source>
        <translation>廠商 ID</translation>
    </message>
    <message>
        <source>Inquire product code</source>
        <translation>查詢產品代碼</translation>
    </message>
    <message>
        <source>Product code</source>
        <translation>產品代碼</translation>
    </message>
    <message>
        <source>Inquire revision number</source>
        <translation>查詢版本號</translation>
    </message>
    <message>
        <source>Revision number</source>
        <translation>版本號</translation>
    </message>
    <message>
        <source>Inquire serial number</source>
        <translation>查詢序號</translation>
    </message>
    <message>
        <source>Serial number</source>
        <translation>序號</translation>
    </message>
    <message>
        <source>Inquire node-ID</source>
        <translation>查詢節點 ID</translation>
    </message>
    <message>
        <source>Identify remote slave: vendor-ID</source>
        <translation>識別遠端從站：廠商 ID</translation>
    </message>
    <message>
        <source>Identify remote slave: product code</source>
        <translation>識別遠端從站：產品代碼</translation>
    </message>
    <message>
        <source>Identify remote slave: revision low</source>
        <translation>識別遠端從站：版本號下限</translation>
    </message>
    <message>
        <source>Identify remote slave: revision high</source>
        <translation>識別遠端從站：版本號上限</translation>
    </message>
    <message>
        <source>Identify remote slave: serial low</source>
        <translation>識別遠端從站：序號下限</translation>
    </message>
    <message>
        <source>Identify remote slave: serial high</source>
        <translation>識別遠端從站：序號上限</translation>
    </message>
    <message>
        <source>Identify non-configured remote slave</source>
        <translation>識別未設定節點 ID 的遠端從站</translation>
    </message>
    <message>
        <source>Identify slave</source>
        <translation>從站識別回應</translation>
    </message>
    <message>
        <source>Identify non-configured slave</source>
        <translation>未設定節點 ID 的從站識別回應</translation>
    </message>
    <message>
        <source>Fastscan</source>
        <translation>快速掃描（Fastscan）</translation>
    </message>
    <message>
        <source>Unknown LSS command 0x%1</source>
        <translation>未知的 LSS 命令 0x%1</translation>
    </message>
    <message>
        <source>LSS %1</source>
        <translation>LSS：%1</translation>
    </message>
    <message>
        <source>LSS %1: configuration</source>
        <translation>LSS：%1（設定狀態）</translation>
    </message>
    <message>
        <source>LSS %1: waiting</source>
        <translation>LSS：%1（等待狀態）</translation>
    </message>
    <message>
        <source>LSS %1: node-ID %2</source>
        <translation>LSS：%1（節點 ID %2）</translation>
    </message>
    <message>
        <source>LSS %1: error %2</source>
        <translation>LSS：%1（錯誤 %2）</translation>
    </message>
    <message>
        <source>LSS %1: ok</source>
        <translation>LSS：%1（成功）</translation>
    </message>
    <message>
        <source>LSS %1: %2 kbit/s</source>
        <translation>LSS：%1（鮑率 %2 kbit/s）</translation>
    </message>
    <message>
        <source>LSS %1: table %2 index %3</source>
        <translation>LSS：%1（表 %2，索引 %3）</translation>
    </message>
    <message>
        <source>LSS %1: delay %2 ms</source>
        <translation>LSS：%1（延遲 %2 ms）</translation>
    </message>
    <message>
        <source>LSS %1: 0x%2</source>
        <translation>LSS：%1 = 0x%2</translation>
    </message>
    <message>
        <source>LSS Node-ID: %1</source>
        <translation>LSS：節點 ID = %1</translation>
    </message>
    <message>
        <source>LSS %1: IDNumber 0x%2, bit %3, sub %4, next %5</source>
        <translation>LSS：%1（識別號 0x%2，檢查位元 %3，比對項 %4，下一項 %5）</translation>
    </message>
    <message>
        <source>LSS (malformed)</source>
        <translation>LSS（格式錯誤）</translation>
    </message>
    <message>
        <source>LSS frame with %1 bytes; CiA 305 requires 8</source>
        <translation>LSS 封包有 %1 位元組；CiA 305 規定為 8</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, register 0x%4, %5</source>
        <translation>EMCY 節點 %1：%2 %3，錯誤暫存器 0x%4，%5</translation>
    </message>
    <message>
        <source>Delta alarm number</source>
        <translation>台達異警號碼</translation>
    </message>
    <message>
        <source>AIMOTOR fault code</source>
        <translation>AIMOTOR 故障碼</translation>
    </message>
    <message>
        <source>M1 alarm code</source>
        <translation>M1 異警碼</translation>
    </message>
    <message>
        <source>M2 alarm code</source>
        <translation>M2 異警碼</translation>
    </message>
    <message>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1、%2</translation>
    </message>
    <message>
        <source>%1: the bus is listen-only: CoScope sends nothing, so no heartbeat and no guard</source>
        <translation>%1：匯流排為僅監聽：CoScope 不發送任何訊框，因此沒有心跳也沒有保護</translation>
    </message>
    <message>
        <source>%1: CoScope&apos;s heartbeat node-ID %2 is the drive&apos;s own; choose another in the master settings</source>
        <translation>%1：CoScope 的心跳節點 ID %2 與驅動器相同；請在主站設定中另選</translation>
    </message>
    <message>
        <source>%1: CoScope&apos;s heartbeat cannot start: %2</source>
        <translation>%1：CoScope 的心跳無法啟動：%2</translation>
    </message>
    <message>
        <source>%1 may still be enabled: it keeps watching CoScope&apos;s heartbeat (1016h, 6007h not put back), so it stops by itself when the heartbeat stops</source>
        <translation>%1 可能仍為致能：它繼續監看 CoScope 的心跳（1016h、6007h 未寫回），心跳停止時會自行停止</translation>
    </message>
    <message>
        <source>%1: the old 1016h/6007h could not be put back (the bus is closed); check them</source>
        <translation>%1：原本的 1016h/6007h 無法寫回（匯流排已關閉）；請檢查</translation>
    </message>
    <message>
        <source>%1: heartbeat consumer 1016h and 6007h put back before the bus closed</source>
        <translation>%1：匯流排關閉前已寫回消費者心跳時間 1016h 與 6007h</translation>
    </message>
    <message>
        <source>%1: the old 1016h/6007h were not all put back (%2); check them</source>
        <translation>%1：原本的 1016h/6007h 未全部寫回（%2）；請檢查</translation>
    </message>
    <message>
        <source>%1 watches CoScope&apos;s heartbeat (node %2) in 1016h:%3 with %4 ms; when it stops: %5</source>
        <translation>%1 以 1016h:%3 監看 CoScope 的心跳（節點 %2），%4 ms；心跳停止時：%5</translation>
    </message>
    <message>
        <source>%1: heartbeat consumer 1016h:%2 = %3%4 put back</source>
        <translation>%1：已寫回消費者心跳時間 1016h:%2 = %3%4</translation>
    </message>
    <message>
        <source>node %1: node guarding answer with toggle bit %2, %3 expected</source>
        <translation>節點 %1：節點保護回應的切換位元為 %2，應為 %3</translation>
    </message>
    <message>
        <source>node %1: no answer to a node guarding request within the guard time %2 ms</source>
        <translation>節點 %1：節點保護請求在守護時間 %2 ms 內無回應</translation>
    </message>
    <message>
        <source>set-point acknowledge</source>
        <translation>設定點確認</translation>
    </message>
    <message>
        <source>following error</source>
        <translation>追隨誤差</translation>
    </message>
    <message>
        <source>zero speed</source>
        <translation>零速度</translation>
    </message>
    <message>
        <source>max slippage error</source>
        <translation>最大滑差錯誤</translation>
    </message>
    <message>
        <source>homing attained</source>
        <translation>原點復歸完成</translation>
    </message>
    <message>
        <source>homing error</source>
        <translation>原點復歸錯誤</translation>
    </message>
    <message>
        <source>ip mode active</source>
        <translation>IP 模式啟用中</translation>
    </message>
    <message>
        <source>drive follows the command value</source>
        <translation>驅動器跟隨命令值</translation>
    </message>
    <message>
        <source>FFh (event)</source>
        <translation>FFh（事件觸發）</translation>
    </message>
    <message>
        <source>FEh (event, manufacturer)</source>
        <translation>FEh（事件觸發，製造商定義）</translation>
    </message>
    <message>
        <source>Current position is home (no movement)</source>
        <translation>目前位置即為原點（不移動）</translation>
    </message>
    <message>
        <source>Current position is home (no movement; the default)</source>
        <translation>目前位置即為原點（不移動；預設）</translation>
    </message>
    <message>
        <source>Home switch searched in the negative direction (stops on its edge)</source>
        <translation>負方向搜尋原點開關（停在其邊緣）</translation>
    </message>
    <message>
        <source>Home switch searched in the negative direction, then the Z pulse</source>
        <translation>負方向搜尋原點開關，再找 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch searched in the positive direction (stops on its edge)</source>
        <translation>正方向搜尋原點開關（停在其邊緣）</translation>
    </message>
    <message>
        <source>Home switch searched in the positive direction, then the Z pulse</source>
        <translation>正方向搜尋原點開關，再找 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: Z pulse above the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: Z pulse below the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: index pulse above the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: index pulse below the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from above (the same as 29, Delta manual §4.6)</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：其邊緣，從上方到達（與 29 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), lower edge: its edge, reached from below</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），下緣：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: Z pulse above the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: Z pulse below the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: index pulse above the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: index pulse below the edge</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from above (the same as 27, Delta manual §4.6)</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：其邊緣，從上方到達（與 27 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, negative start (negative limit switch reverses), upper edge: its edge, reached from below</source>
        <translation>原點開關，負方向起始（負方向極限開關反向），上緣：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: Z pulse above the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: Z pulse below the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: index pulse above the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: index pulse below the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from above</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), lower edge: its edge, reached from below (the same as 23, Delta manual §4.6)</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），下緣：其邊緣，從下方到達（與 23 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: Z pulse above the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: Z pulse below the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: index pulse above the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: index pulse below the edge</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from above</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Home switch, positive start (positive limit switch reverses), upper edge: its edge, reached from below (the same as 25, Delta manual §4.6)</source>
        <translation>原點開關，正方向起始（正方向極限開關反向），上緣：其邊緣，從下方到達（與 25 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Mechanical end stop in the negative direction, at low speed with the homing torque limit H05-58</source>
        <translation>負方向低速搜尋機械極限位置，扭矩限制為原點復歸扭矩限制 H05-58</translation>
    </message>
    <message>
        <source>Mechanical end stop in the positive direction, at low speed with the homing torque limit H05-58</source>
        <translation>正方向低速搜尋機械極限位置，扭矩限制為原點復歸扭矩限制 H05-58</translation>
    </message>
    <message>
        <source>Negative home switch: Z pulse above the edge</source>
        <translation>負方向原點開關：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Negative home switch: Z pulse below the edge</source>
        <translation>負方向原點開關：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Negative home switch: index pulse above the edge</source>
        <translation>負方向原點開關：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Negative home switch: index pulse below the edge</source>
        <translation>負方向原點開關：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from above</source>
        <translation>負方向原點開關：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from above (the same as 21, Delta manual §4.6)</source>
        <translation>負方向原點開關：其邊緣，從上方到達（與 21 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Negative home switch: its edge, reached from below</source>
        <translation>負方向原點開關：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Negative limit switch, then back to the first Z pulse</source>
        <translation>負方向極限開關，再回到第一個 Z 脈波</translation>
    </message>
    <message>
        <source>Negative limit switch, then back to the first index pulse</source>
        <translation>負方向極限開關，再回到第一個索引脈波</translation>
    </message>
    <message>
        <source>Negative limit switch: its edge, backing off the switch</source>
        <translation>負方向極限開關：離開開關時的邊緣</translation>
    </message>
    <message>
        <source>Negative overtravel switch (stops on its edge)</source>
        <translation>反向超程開關（停在其邊緣）</translation>
    </message>
    <message>
        <source>Negative overtravel switch, then the Z pulse</source>
        <translation>反向超程開關，再找 Z 脈波</translation>
    </message>
    <message>
        <source>Next Z pulse in the negative direction</source>
        <translation>負方向的下一個 Z 脈波</translation>
    </message>
    <message>
        <source>Next Z pulse in the positive direction</source>
        <translation>正方向的下一個 Z 脈波</translation>
    </message>
    <message>
        <source>Next index pulse in the negative direction</source>
        <translation>負方向的下一個索引脈波</translation>
    </message>
    <message>
        <source>Next index pulse in the positive direction</source>
        <translation>正方向的下一個索引脈波</translation>
    </message>
    <message>
        <source>Positive home switch: Z pulse above the edge</source>
        <translation>正方向原點開關：邊緣上方的 Z 脈波</translation>
    </message>
    <message>
        <source>Positive home switch: Z pulse below the edge</source>
        <translation>正方向原點開關：邊緣下方的 Z 脈波</translation>
    </message>
    <message>
        <source>Positive home switch: index pulse above the edge</source>
        <translation>正方向原點開關：邊緣上方的索引脈波</translation>
    </message>
    <message>
        <source>Positive home switch: index pulse below the edge</source>
        <translation>正方向原點開關：邊緣下方的索引脈波</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from above</source>
        <translation>正方向原點開關：其邊緣，從上方到達</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from below</source>
        <translation>正方向原點開關：其邊緣，從下方到達</translation>
    </message>
    <message>
        <source>Positive home switch: its edge, reached from below (the same as 19, Delta manual §4.6)</source>
        <translation>正方向原點開關：其邊緣，從下方到達（與 19 相同，台達手冊 §4.6）</translation>
    </message>
    <message>
        <source>Positive limit switch, then back to the first Z pulse</source>
        <translation>正方向極限開關，再回到第一個 Z 脈波</translation>
    </message>
    <message>
        <source>Positive limit switch, then back to the first index pulse</source>
        <translation>正方向極限開關，再回到第一個索引脈波</translation>
    </message>
    <message>
        <source>Positive limit switch: its edge, backing off the switch</source>
        <translation>正方向極限開關：離開開關時的邊緣</translation>
    </message>
    <message>
        <source>Positive overtravel switch (stops on its edge)</source>
        <translation>正向超程開關（停在其邊緣）</translation>
    </message>
    <message>
        <source>Positive overtravel switch, then the Z pulse</source>
        <translation>正向超程開關，再找 Z 脈波</translation>
    </message>
    <message>
        <source>Z pulse searched in the negative direction</source>
        <translation>負方向搜尋 Z 脈波</translation>
    </message>
    <message>
        <source>Z pulse searched in the positive direction</source>
        <translation>正方向搜尋 Z 脈波</translation>
    </message>
    <message>
        <source>No reason given</source>
        <translation>未說明原因</translation>
    </message>
</context>
<context>
    <name>Ds402Fault</name>
    <message>
        <source>Error code (603Fh) %1h</source>
        <extracomment>CiA 402 wizard, a drive fault: %1 = the error code in hex</extracomment>
        <translation>錯誤碼（603Fh）%1h</translation>
    </message>
    <message>
        <source> — vendor alarm %1</source>
        <extracomment>CiA 402 wizard, after the error code: %1 = the vendor&apos;s alarm code and name (&quot;AL013 Emergency stop&quot;)</extracomment>
        <translation>——廠商異警 %1</translation>
    </message>
    <message>
        <source>alarm number 0x%1 (not in the %2 table)</source>
        <extracomment>%1 = the vendor alarm number in hex, %2 = the alarm table&apos;s name (e.g. delta-asda-a2)</extracomment>
        <translation>異警編號 0x%1（不在 %2 異警表中）</translation>
    </message>
</context>
<context>
    <name>Ds402StateDiagram</name>
    <message>
        <source>13 any fault</source>
        <translation>13 任何故障</translation>
    </message>
</context>
<context>
    <name>Ds402VendorNotes</name>
    <message>
        <source>P1-01 must be 0x0C (standard CANopen mode) or the drive ignores the controlword. Do not send NMT Reset Node while the servo is on: the drive raises AL401.</source>
        <translation>P1-01 必須為 0x0C（標準 CANopen 模式），否則驅動器會忽略控制字。伺服啟動（Servo On）時請勿送出 NMT Reset Node：驅動器會發出 AL401。</translation>
    </message>
    <message>
        <source>H02-00 must be 8 (CANopen control) or the drive ignores the controlword.</source>
        <translation>H02-00 必須為 8（CANopen 控制），否則驅動器會忽略控制字。</translation>
    </message>
    <message>
        <source>The DEXMART DEV has no CiA 402 state machine: its two motors are run through the Multi-Drive objects (3051h/3052h). Use the Object dictionary dock for it.</source>
        <translation>DEXMART DEV 沒有 CiA 402 狀態機：它的兩台馬達是透過 Multi-Drive 物件（3051h/3052h）控制。請改用物件字典面板。</translation>
    </message>
</context>
<context>
    <name>EnabledDrivesQuestion</name>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and quit?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並結束嗎？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and quit?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並結束嗎？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and disconnect?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並中斷連線嗎？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and disconnect?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並中斷連線嗎？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and connect anew?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並重新連線嗎？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and connect anew?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並重新連線嗎？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope: disable it and open the log?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並開啟記錄檔嗎？</translation>
    </message>
    <message>
        <source>Nodes %1 are enabled by CoScope: disable them and open the log?</source>
        <translation>節點 %1 由 CoScope 致能中：要將其停用並開啟記錄檔嗎？</translation>
    </message>
    <message>
        <source>%1 (axis %2)</source>
        <translation>%1（軸 %2）</translation>
    </message>
    <message>
        <source>Drive enabled</source>
        <translation>驅動器致能中</translation>
    </message>
    <message>
        <source>CoScope sends Disable voltage (6040h = 0000h; Quick stop first to a drive that may be moving) and waits to see it on the bus before the connection closes. Cancel leaves everything as it is.</source>
        <translation>CoScope 會送出切斷電壓（Disable voltage，6040h = 0000h；可能在移動的驅動器先送快速停止（Quick Stop）），並在連線關閉前等待在匯流排上看到該訊框。取消則一切維持原狀。</translation>
    </message>
    <message>
        <source>Disable and quit</source>
        <translation>停用並結束</translation>
    </message>
    <message>
        <source>Disable and disconnect</source>
        <translation>停用並中斷連線</translation>
    </message>
    <message>
        <source>Disable and connect</source>
        <translation>停用並連線</translation>
    </message>
    <message>
        <source>Disable and open the log</source>
        <translation>停用並開啟記錄檔</translation>
    </message>
</context>
<context>
    <name>EventLog</name>
    <message>
        <source>EMCY reset</source>
        <translation>EMCY 重置</translation>
    </message>
    <message>
        <source>SDO abort</source>
        <translation>SDO 中止</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 狀態</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>上線（Boot-up）</translation>
    </message>
    <message>
        <source>NMT command</source>
        <translation>NMT 命令</translation>
    </message>
    <message>
        <source>Heartbeat timeout</source>
        <translation>心跳逾時</translation>
    </message>
    <message>
        <source>Bus error</source>
        <translation>匯流排錯誤</translation>
    </message>
    <message>
        <source>Dropped frames</source>
        <translation>遺失的封包</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>資訊</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有節點</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Heartbeat back after timeout</source>
        <translation>逾時後心跳恢復</translation>
    </message>
    <message>
        <source>State %1</source>
        <translation>狀態 %1</translation>
    </message>
    <message>
        <source>No heartbeat for %1 ms (period %2 ms)</source>
        <translation>%1 ms 內沒有心跳（週期 %2 ms）</translation>
    </message>
    <message>
        <source>error</source>
        <translation>錯誤</translation>
    </message>
    <message>
        <source>warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>info</source>
        <translation>資訊</translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message>
        <source>NMT (short frame)</source>
        <translation>NMT（短封包）</translation>
    </message>
    <message>
        <source>NMT frame must carry 2 bytes</source>
        <translation>NMT 封包必須有 2 個位元組</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有節點</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>NMT node control</source>
        <translation>NMT 節點控制</translation>
    </message>
    <message>
        <source>Command specifier</source>
        <translation>命令識別碼</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <source>0 (all)</source>
        <translation>0（全部）</translation>
    </message>
    <message>
        <source>Node guarding request to node %1</source>
        <translation>對節點 %1 的節點保護請求</translation>
    </message>
    <message>
        <source>Node guarding request (RTR)</source>
        <translation>節點保護請求（RTR）</translation>
    </message>
    <message>
        <source>NMT error control (empty)</source>
        <translation>NMT 錯誤控制（空）</translation>
    </message>
    <message>
        <source>error control frame without state byte</source>
        <translation>錯誤控制封包缺少狀態位元組</translation>
    </message>
    <message>
        <source>Boot-up node %1</source>
        <translation>節點 %1 上線（Boot-up）</translation>
    </message>
    <message>
        <source>Heartbeat node %1: %2</source>
        <translation>節點 %1 心跳：%2</translation>
    </message>
    <message>
        <source>Boot-up</source>
        <translation>上線（Boot-up）</translation>
    </message>
    <message>
        <source>Heartbeat / guarding</source>
        <translation>心跳／節點保護</translation>
    </message>
    <message>
        <source>Toggle</source>
        <translation>切換位元</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 狀態</translation>
    </message>
    <message>
        <source>EMCY node %1: error reset</source>
        <translation>EMCY 節點 %1：錯誤重置</translation>
    </message>
    <message>
        <source>EMCY node %1: %2 %3, reg %4</source>
        <translation>EMCY 節點 %1：%2 %3，暫存器 %4</translation>
    </message>
    <message>
        <source>EMCY frame shorter than 8 bytes</source>
        <translation>EMCY 封包短於 8 位元組</translation>
    </message>
    <message>
        <source>Emergency</source>
        <translation>緊急訊息</translation>
    </message>
    <message>
        <source>Error code</source>
        <translation>錯誤碼</translation>
    </message>
    <message>
        <source>Error register (1001h)</source>
        <translation>錯誤暫存器（1001h）</translation>
    </message>
    <message>
        <source>Bit %1</source>
        <translation>位元 %1</translation>
    </message>
    <message>
        <source>Manufacturer-specific</source>
        <translation>製造商定義</translation>
    </message>
    <message>
        <source>SDO %1 node %2 %3</source>
        <translation>SDO %1 節點 %2 %3</translation>
    </message>
    <message>
        <source>, %1 bytes</source>
        <translation>，%1 位元組</translation>
    </message>
    <message>
        <source>SDO request (client → server)</source>
        <translation>SDO 請求（用戶端 → 伺服器）</translation>
    </message>
    <message>
        <source>SDO response (server → client)</source>
        <translation>SDO 回應（伺服器 → 用戶端）</translation>
    </message>
    <message>
        <source>Command</source>
        <translation>命令</translation>
    </message>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Sub-index</source>
        <translation>子索引</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止碼</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Segment data</source>
        <translation>分段資料</translation>
    </message>
    <message>
        <source>Error frame, class %1</source>
        <translation>錯誤封包，類別 %1</translation>
    </message>
    <message>
        <source>Error frame</source>
        <translation>錯誤封包</translation>
    </message>
    <message>
        <source>SYNC counter %1</source>
        <translation>SYNC 計數器 %1</translation>
    </message>
    <message>
        <source>TIME stamp</source>
        <translation>時間戳記（TIME）</translation>
    </message>
    <message>
        <source>(empty)</source>
        <translation>（空）</translation>
    </message>
    <message>
        <source>LSS command</source>
        <translation>LSS 命令</translation>
    </message>
    <message>
        <source>(29-bit identifier, not CANopen)</source>
        <translation>（29 位元識別碼，非 CANopen）</translation>
    </message>
    <message>
        <source>%1 node %2, %3 bytes</source>
        <translation>%1 節點 %2，%3 位元組</translation>
    </message>
</context>
<context>
    <name>GapSaveQuestion</name>
    <message>
        <source>Save trace</source>
        <translation>儲存追蹤</translation>
    </message>
    <message numerus="yes">
        <source>The trace has %n gap(s) (adapter lost); the %1 format cannot hold them, so the saved file will not show where frames are missing. pcapng, ASC, TRC and CSV keep them.</source>
        <translation>
            <numerusform>追蹤中有 %n 處中斷（轉接器遺失）；%1 格式無法保存中斷，存檔後將看不出哪裡缺少封包。pcapng、ASC、TRC 與 CSV 會保留中斷。</numerusform>
        </translation>
    </message>
    <message>
        <source>Save anyway</source>
        <translation>仍要儲存</translation>
    </message>
</context>
<context>
    <name>HealthRules</name>
    <message>
        <source>Node %1 booted up %2 time(s) without an NMT reset command before it.</source>
        <translation>節點 %1 在沒有 NMT 重置命令的情況下上線了 %2 次。</translation>
    </message>
    <message>
        <source>A device that restarts on its own loses its state: a drive drops its enable and the machine stops.</source>
        <translation>設備自行重新啟動會失去原有狀態：驅動器失去致能，機台隨之停止。</translation>
    </message>
    <message>
        <source>Check the node&apos;s supply voltage and wiring, its watchdog and error history, and the frames just before each boot-up.</source>
        <translation>請檢查該節點的電源電壓與配線、看門狗與錯誤紀錄，以及每次上線前的封包。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 stopped: nothing for %3 at the end of the log (period %4).</source>
        <translation>節點 %1 的%2已停止：記錄結尾有 %3 沒有任何訊息（週期 %4）。</translation>
    </message>
    <message>
        <source>The master&apos;s heartbeat consumer sees the node as lost and the application stops using it.</source>
        <translation>主站的心跳消費者會判定此節點遺失，應用程式便停止使用它。</translation>
    </message>
    <message>
        <source>Check that node %1 still has power and is on the bus (cable, connector, termination), and whether its 1017h was set to 0.</source>
        <translation>請確認節點 %1 仍有電源且連在匯流排上（電纜、接頭、終端電阻），並檢查其 1017h 是否被設為 0。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 was missing %3 time(s) after regular beats (longest gap %4, period %5).</source>
        <translation>節點 %1 的%2在規律發送後中斷了 %3 次（最長間隔 %4，週期 %5）。</translation>
    </message>
    <message>
        <source>A consumer whose heartbeat time (1016h) is shorter than the gap raises a heartbeat error and may stop the machine.</source>
        <translation>消費者心跳時間（1016h）短於此間隔時，會產生心跳錯誤並可能使機台停止。</translation>
    </message>
    <message>
        <source>Look at the frames around each gap: error frames, bus load, a reset of node %1, a loose connection.</source>
        <translation>請查看每個間隔前後的封包：錯誤封包、匯流排負載、節點 %1 是否重置、接線是否鬆脫。</translation>
    </message>
    <message>
        <source>Node %1&apos;s %2 came late %3 time(s) (over 1.5 times the %4 period).</source>
        <translation>節點 %1 的%2延遲了 %3 次（超過週期 %4 的 1.5 倍）。</translation>
    </message>
    <message>
        <source>Late beats eat the consumer&apos;s margin: a little more delay becomes a heartbeat error.</source>
        <translation>延遲的心跳會吃掉消費者的裕度：再多一點延遲就會變成心跳錯誤。</translation>
    </message>
    <message>
        <source>Compare with the bus load at those times, and check that the consumer time (1016h) leaves margin over %4.</source>
        <translation>請對照當時的匯流排負載，並確認消費者時間（1016h）比 %4 留有裕度。</translation>
    </message>
    <message>
        <source>Node %1 reported EMCY %2 (%3) %4 time(s).</source>
        <translation>節點 %1 回報了 EMCY %2（%3）共 %4 次。</translation>
    </message>
    <message>
        <source>The device signals a fault; a drive in Fault stops its motor until the fault is reset.</source>
        <translation>設備發出故障訊號；驅動器處於故障狀態時會停止馬達，直到故障重置。</translation>
    </message>
    <message>
        <source>Look up %2 in the device&apos;s alarm list, remove the cause, then reset the fault (controlword bit 7).</source>
        <translation>請在設備的異警表中查詢 %2，排除原因後再重置故障（控制字 bit 7）。</translation>
    </message>
    <message>
        <source>Node %1 left %2 SDO request(s) unanswered (no response within 1 s).</source>
        <translation>節點 %1 有 %2 個 SDO 請求未回應（1 秒內沒有回覆）。</translation>
    </message>
    <message>
        <source>The master&apos;s parameter access fails: a configuration step may have been skipped.</source>
        <translation>主站的參數存取失敗：可能有設定步驟被略過。</translation>
    </message>
    <message>
        <source>Check node %1&apos;s node-ID, power and NMT state (a stopped node serves no SDO), and the bus load at those times.</source>
        <translation>請檢查節點 %1 的節點 ID、電源與 NMT 狀態（停止狀態的節點不處理 SDO），以及當時的匯流排負載。</translation>
    </message>
    <message>
        <source>Node %1 aborted %4 SDO transfer(s) with %2 (%3).</source>
        <translation>節點 %1 以 %2（%3）中止了 %4 次 SDO 傳輸。</translation>
    </message>
    <message>
        <source>The value was not read or written: a configuration that relies on it is incomplete.</source>
        <translation>該值沒有被讀取或寫入：依賴它的設定並不完整。</translation>
    </message>
    <message>
        <source>Look at the object of each frame: does node %1 have it (its EDS), is it writable, is the value in range?</source>
        <translation>請查看每個封包的物件：節點 %1 是否有此物件（見其 EDS）、是否可寫、數值是否在範圍內？</translation>
    </message>
    <message>
        <source>Node %1 answered SDO requests slowly: %2 at the 99th percentile, the slowest %3.</source>
        <translation>節點 %1 回應 SDO 請求很慢：第 99 百分位數為 %2，最慢 %3。</translation>
    </message>
    <message>
        <source>A master with a short SDO timeout aborts such transfers, and start-up configuration takes longer.</source>
        <translation>SDO 逾時設定較短的主站會中止這類傳輸，開機時的設定也會花更久。</translation>
    </message>
    <message>
        <source>Check what node %1 does meanwhile (storing parameters, 1010h) and the bus load; raise the master&apos;s SDO timeout if needed.</source>
        <translation>請檢查節點 %1 當時在做什麼（儲存參數，1010h）以及匯流排負載；必要時加長主站的 SDO 逾時。</translation>
    </message>
    <message>
        <source>%1 CAN error frame(s) were recorded.</source>
        <translation>記錄到 %1 個 CAN 錯誤封包。</translation>
    </message>
    <message>
        <source>Error frames destroy frames and delay others; many of them take nodes to error passive or bus-off.</source>
        <translation>錯誤封包會破壞封包並延遲其他封包；數量一多，節點就會進入錯誤被動或匯流排關閉狀態。</translation>
    </message>
    <message>
        <source>Check the termination (120 ohm at both ends), cable, shield and ground, and that every node uses the same bit rate.</source>
        <translation>請檢查終端電阻（兩端各 120 歐姆）、電纜、屏蔽與接地，並確認所有節點使用相同的鮑率。</translation>
    </message>
    <message>
        <source>%1 SYNC cycle(s) were missing (period %2).</source>
        <translation>缺少了 %1 個 SYNC 週期（週期 %2）。</translation>
    </message>
    <message>
        <source>Synchronous PDOs are not sent or applied in those cycles; axes in a cyclic synchronous mode miss set-points.</source>
        <translation>這些週期內同步 PDO 不會送出或套用；處於週期同步模式的軸會漏掉命令值。</translation>
    </message>
    <message>
        <source>Check the SYNC producer&apos;s timing and load, and the bus load at those times.</source>
        <translation>請檢查 SYNC 生產者的時序與負載，以及當時的匯流排負載。</translation>
    </message>
    <message>
        <source>The bus load peaks at %1 % (average %2 %) at %3 bit/s.</source>
        <translation>匯流排負載峰值為 %1 %（平均 %2 %），鮑率 %3 bit/s。</translation>
    </message>
    <message>
        <source>Above about 70 % the low-priority frames (SDO, heartbeat) wait and may time out.</source>
        <translation>負載超過約 70 % 時，低優先權的封包（SDO、心跳）會等待並可能逾時。</translation>
    </message>
    <message>
        <source>Lower PDO rates or mapped data, use inhibit times or event timers, or raise the bit rate.</source>
        <translation>請降低 PDO 頻率或映射的資料量、使用禁止時間或事件計時器，或提高鮑率。</translation>
    </message>
    <message>
        <source>%1 (%2) is sent to node %3, which never sent anything.</source>
        <translation>%1（%2）送往節點 %3，但該節點從未送出任何訊息。</translation>
    </message>
    <message>
        <source>The data goes nowhere: node %3 is missing or has another node-ID.</source>
        <translation>資料沒有接收者：節點 %3 不存在或使用了其他節點 ID。</translation>
    </message>
    <message>
        <source>Check that node %3 is powered and on the bus, and its node-ID.</source>
        <translation>請確認節點 %3 有電源且連在匯流排上，並檢查其節點 ID。</translation>
    </message>
    <message>
        <source>%1 of node %2 (%3) comes every %4 with a jitter of %5.</source>
        <translation>節點 %2 的 %1（%3）每 %4 一次，抖動為 %5。</translation>
    </message>
    <message>
        <source>Cyclic data that arrives unevenly makes control and plots uneven.</source>
        <translation>週期資料到達不均勻，會使控制與圖表也不均勻。</translation>
    </message>
    <message>
        <source>Check the producer&apos;s timing (SYNC or event timer) and the bus load; the frames listed end the most irregular intervals.</source>
        <translation>請檢查生產者的時序（SYNC 或事件計時器）與匯流排負載；列出的封包是最不規律間隔的結尾。</translation>
    </message>
    <message>
        <source>RPDO%1 of node %2 (%3) is valid but nobody sends it.</source>
        <translation>節點 %2 的 RPDO%1（%3）已啟用，但沒有人送出它。</translation>
    </message>
    <message>
        <source>Node %2 waits for data that never comes; with an RPDO timeout it may fault.</source>
        <translation>節點 %2 在等待永遠不會來的資料；若設有 RPDO 逾時，可能會進入故障。</translation>
    </message>
    <message>
        <source>Map and enable the matching TPDO on the producer, or make this RPDO invalid (COB-ID bit 31).</source>
        <translation>請在生產者上映射並啟用對應的 TPDO，或將此 RPDO 設為無效（COB-ID bit 31）。</translation>
    </message>
    <message>
        <source>%1 node-ID(s) (%2..%3) got an SDO request from a master and never answered.</source>
        <translation>有 %1 個節點 ID（%2..%3）收到主站的 SDO 請求但從未回應。</translation>
    </message>
    <message>
        <source>A device the master expects may be missing, or the master scanned the network.</source>
        <translation>主站預期的設備可能不存在，或主站正在掃描網路。</translation>
    </message>
    <message>
        <source>Compare with the devices the machine should have, and their node-IDs.</source>
        <translation>請對照機台應有的設備及其節點 ID。</translation>
    </message>
    <message>
        <source>%1 frame(s) are not CANopen.</source>
        <translation>有 %1 個封包不是 CANopen。</translation>
    </message>
    <message>
        <source>They come from another protocol on the same bus (such as J1939) or from a device set up wrongly.</source>
        <translation>它們來自同一匯流排上的其他協定（例如 J1939），或來自設定錯誤的設備。</translation>
    </message>
    <message>
        <source>Look at their identifiers in the trace.</source>
        <translation>請在追蹤中查看它們的識別碼。</translation>
    </message>
    <message>
        <source>CoScope&apos;s scan (frames sent by the recording side) asked %1 node-ID(s) (%2..%3) that did not answer.</source>
        <translation>CoScope 的掃描（記錄端送出的封包）詢問了 %1 個沒有回應的節點 ID（%2..%3）。</translation>
    </message>
    <message>
        <source>This is how a scan finds devices: no device is at fault.</source>
        <translation>掃描就是這樣找出設備的：沒有任何設備有問題。</translation>
    </message>
    <message>
        <source>Nothing to fix: these requests are CoScope&apos;s own.</source>
        <translation>無需處理：這些請求是 CoScope 自己送出的。</translation>
    </message>
    <message>
        <source>Node %1 aborted %4 SDO request(s) that CoScope sent, with %2 (%3).</source>
        <translation>節點 %1 以 %2（%3）中止了 CoScope 送出的 %4 個 SDO 請求。</translation>
    </message>
    <message>
        <source>CoScope&apos;s own requests (a scan reading optional objects, a read or write of the user) caused them: not a device fault.</source>
        <translation>這是 CoScope 自己的請求（掃描讀取選用物件、使用者的讀寫）所造成：不是設備故障。</translation>
    </message>
    <message>
        <source>Nothing to fix unless you expected node %1 to have that object.</source>
        <translation>除非您預期節點 %1 應有該物件，否則無需處理。</translation>
    </message>
    <message>
        <source>Node %1 did not answer %2 SDO request(s) that CoScope sent.</source>
        <translation>節點 %1 沒有回應 CoScope 送出的 %2 個 SDO 請求。</translation>
    </message>
    <message>
        <source>CoScope&apos;s own requests went unanswered (a scan probing, or the node was busy): not counted as a device fault.</source>
        <translation>CoScope 自己的請求沒有得到回應（掃描探測，或節點忙碌）：不算設備故障。</translation>
    </message>
    <message>
        <source>Nothing to fix unless node %1 should have answered.</source>
        <translation>除非節點 %1 應該回應，否則無需處理。</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>guarding</source>
        <translation>節點保護</translation>
    </message>
</context>
<context>
    <name>HelpMenu</name>
    <message>
        <source>&amp;Help</source>
        <translation>說明(&amp;H)</translation>
    </message>
    <message>
        <source>CoScope &amp;guide</source>
        <translation>CoScope 使用指南(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵(&amp;K)</translation>
    </message>
    <message>
        <source>&amp;About CoScope</source>
        <translation>關於 CoScope(&amp;A)</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>關於 Qt(&amp;Q)</translation>
    </message>
</context>
<context>
    <name>LogLoadJob</name>
    <message>
        <source>Opening %1</source>
        <translation>正在開啟 %1</translation>
    </message>
    <message>
        <source>%1: cannot open</source>
        <translation>%1：無法開啟</translation>
    </message>
</context>
<context>
    <name>LogSaveJob</name>
    <message>
        <source>Saving %1</source>
        <translation>正在儲存 %1</translation>
    </message>
    <message>
        <source>%1: unknown log format</source>
        <translation>%1：未知的記錄檔格式</translation>
    </message>
    <message>
        <source>%1: cannot write format &apos;%2&apos;</source>
        <translation>%1：無法寫入格式「%2」</translation>
    </message>
</context>
<context>
    <name>OdTreeModel</name>
    <message>
        <source>sub %1</source>
        <translation>子索引 %1</translation>
    </message>
    <message>
        <source>reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message>
        <source>writing…</source>
        <translation>寫入中…</translation>
    </message>
    <message>
        <source>, PDO-mappable</source>
        <translation>，可映射到 PDO</translation>
    </message>
    <message>
        <source>
Limits: %1 … %2</source>
        <translation>
範圍：%1 … %2</translation>
    </message>
    <message>
        <source>
Differs from the default</source>
        <translation>
與預設值不同</translation>
    </message>
    <message>
        <source>node %1 %2: %3</source>
        <translation>節點 %1 %2：%3</translation>
    </message>
    <message>
        <source>node %1 %2: %3 (bytes %4)</source>
        <translation>節點 %1 %2：%3（位元組 %4）</translation>
    </message>
    <message>
        <source>
Bits on: %1</source>
        <translation>
已設定的位元：%1</translation>
    </message>
</context>
<context>
    <name>OpenFailure</name>
    <message>
        <source>Open log</source>
        <translation>開啟記錄檔</translation>
    </message>
    <message>
        <source>%1 could not be opened as a CAN log.</source>
        <translation>無法將 %1 當作 CAN 記錄檔開啟。</translation>
    </message>
    <message>
        <source>Nothing was changed: the trace, nodes and signals shown are kept.</source>
        <translation>沒有任何變更：目前顯示的追蹤、節點與訊號都保留。</translation>
    </message>
    <message>
        <source>Reading %1 stopped at an error.</source>
        <translation>讀取 %1 時因錯誤而停止。</translation>
    </message>
    <message>
        <source>The %L1 frames read before it are shown.</source>
        <translation>顯示錯誤之前讀到的 %L1 個封包。</translation>
    </message>
</context>
<context>
    <name>PdoDbcExport</name>
    <message>
        <source>%1: cannot write the DBC file (%2)</source>
        <translation>%1：無法寫入 DBC 檔案（%2）</translation>
    </message>
    <message>
        <source>PDO layout exported to %1: %2 PDO messages, %3 raw signals</source>
        <translation>PDO 配置已匯出至 %1：%2 個 PDO 訊息，%3 個原始訊號</translation>
    </message>
    <message>
        <source>Export PDO layout as DBC</source>
        <translation>將 PDO 配置匯出為 DBC</translation>
    </message>
    <message>
        <source>DBC file (*.dbc)</source>
        <translation>DBC 檔案（*.dbc）</translation>
    </message>
    <message>
        <source>Exporting the PDO layout</source>
        <translation>正在匯出 PDO 配置</translation>
    </message>
</context>
<context>
    <name>PdoVendorNotes</name>
    <message>
        <source>Delta ASDA-A2: the drive speaks standard CANopen only when P1-01 (2101h) = 0x0C; check it first.</source>
        <translation>台達 ASDA-A2：只有在 P1-01（2101h）= 0x0C 時，驅動器才使用標準 CANopen；請先檢查此參數。</translation>
    </message>
    <message>
        <source>Delta writes every P-parameter (2000h–2FFFh) to EEPROM on each SDO write; P-parameters written by PDO are stored only when P3-11 X = 1 (wears the EEPROM).</source>
        <translation>台達每次以 SDO 寫入 P 參數（2000h–2FFFh）都會寫入 EEPROM；以 PDO 寫入的 P 參數只有在 P3-11 X = 1 時才會儲存（會耗損 EEPROM）。</translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. Two PDOs with the same COB-ID within 1 ms raise alarm AL112.</source>
        <translation>每個 PDO 最多 8 個物件。兩個 PDO 在 1 ms 內使用相同的 COB-ID 會觸發異警 AL112。</translation>
    </message>
    <message>
        <source>RPDOs with a transmission type 0–240 act at the next SYNC: the master must send SYNC every cycle.</source>
        <translation>傳輸類型 0–240 的 RPDO 在下一個 SYNC 生效：主站必須在每個週期送出 SYNC。</translation>
    </message>
    <message>
        <source>AIMOTOR: CiA 402 objects act only when H02-00 (2002h:01) = 8 (CANopen control).</source>
        <translation>AIMOTOR：只有在 H02-00（2002h:01）= 8（CANopen 控制）時，CiA 402 物件才會生效。</translation>
    </message>
    <message>
        <source>AIMOTOR&apos;s default PDOs are synchronous (type 1): they are sent or applied only when a SYNC arrives. Start a SYNC producer, or choose an event-driven type.</source>
        <translation>AIMOTOR 的預設 PDO 為同步型（類型 1）：只有收到 SYNC 時才會送出或套用。請啟動 SYNC 產生者，或改選事件觸發類型。</translation>
    </message>
    <message>
        <source>Only CiA 402 objects (6000h–6FFFh) can be mapped; at most 8 objects per PDO.</source>
        <translation>只能映射 CiA 402 物件（6000h–6FFFh）；每個 PDO 最多 8 個物件。</translation>
    </message>
    <message>
        <source>DEXMART DEV: the COB-ID is read-only, so a PDO cannot be switched off while it is remapped: the mapping changes while the message is in use.</source>
        <translation>DEXMART DEV：COB-ID 為唯讀，重新映射時無法關閉 PDO：映射會在訊息使用中變更。</translation>
    </message>
    <message>
        <source>At most 8 objects per PDO. The power-on mapping comes from parameter 09-26; a change made here is lost at power-off unless stored.</source>
        <translation>每個 PDO 最多 8 個物件。上電時的映射來自參數 09-26；在此所做的變更若未儲存，斷電後就會遺失。</translation>
    </message>
    <message>
        <source>Two motors: the M1/M2 values live in the Multi-Drive objects (3046h status, 3051h commands).</source>
        <translation>兩台馬達：M1/M2 的值位於 Multi-Drive 物件中（3046h 狀態，3051h 命令）。</translation>
    </message>
    <message>
        <source>No dictionary is known for this node: objects cannot be offered by name. Scan the node (Nodes dock) or assign a dictionary first.</source>
        <translation>此節點沒有已知的字典：無法依名稱列出物件。請先掃描節點（節點面板）或指定字典。</translation>
    </message>
    <message>
        <source>The drive did not answer in time. Check that it is powered, that its node-ID is right, and the cable, termination and bit rate.</source>
        <translation>驅動器未及時回應。請確認它已通電、節點 ID 正確，並檢查纜線、終端電阻與鮑率。</translation>
    </message>
    <message>
        <source>The drive does not allow this object in a PDO. Take another object, or check the manual&apos;s &quot;PDO&quot; column for it.</source>
        <translation>驅動器不允許將此物件放入 PDO。請改選其他物件，或查閱手冊中該物件的「PDO」欄。</translation>
    </message>
    <message>
        <source>Too much data for one PDO on this drive: use fewer objects or smaller ones (at most 64 bits; some drives allow at most 8 objects).</source>
        <translation>此驅動器的單一 PDO 資料過多：請減少物件或改用較短的物件（最多 64 位元；部分驅動器每個 PDO 最多 8 個物件）。</translation>
    </message>
    <message>
        <source>The drive reports a general parameter incompatibility: check that the PDO number exists and the values fit together.</source>
        <translation>驅動器回報一般性參數不相容：請確認此 PDO 編號存在，且各數值彼此相符。</translation>
    </message>
    <message>
        <source>This parameter is read-only on this drive (some drives fix the COB-ID). Keep the current value.</source>
        <translation>此參數在此驅動器上為唯讀（部分驅動器的 COB-ID 固定）。請保留目前的值。</translation>
    </message>
    <message>
        <source>The drive does not have this object: this PDO number may not exist on it.</source>
        <translation>驅動器沒有此物件：它可能沒有這個編號的 PDO。</translation>
    </message>
    <message>
        <source>The drive refused the value: check the allowed range (transmission type, inhibit time, event timer).</source>
        <translation>驅動器拒絕此值：請檢查允許的範圍（傳輸類型、禁止時間、事件計時器）。</translation>
    </message>
    <message>
        <source>The drive does not accept this in its present state. It must be pre-operational (the wizard sends that first)</source>
        <translation>驅動器在目前狀態下不接受此操作。它必須處於預操作狀態（精靈會先送出此命令）</translation>
    </message>
    <message>
        <source>Look up abort code 0x%1 in the drive&apos;s manual.</source>
        <translation>請在驅動器手冊中查詢中止碼 0x%1。</translation>
    </message>
    <message>
        <source>The values read back differ from those written: the drive may have adjusted or ignored one. Read the PDO again and compare.</source>
        <translation>讀回的值與寫入的不同：驅動器可能調整或忽略了其中一個。請重新讀取 PDO 並比較。</translation>
    </message>
    <message>
        <source>Sent at the next SYNC after a value changed (synchronous acyclic, type 0)</source>
        <translation>值變化後在下一個 SYNC 送出（同步非週期，類型 0）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 0)</source>
        <translation>在下一個 SYNC 套用（同步，類型 0）</translation>
    </message>
    <message>
        <source>Sent on every SYNC (synchronous cyclic, type 1)</source>
        <translation>每個 SYNC 都送出（同步週期，類型 1）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type 1)</source>
        <translation>在下一個 SYNC 套用（同步，類型 1）</translation>
    </message>
    <message>
        <source>Sent once every %1 SYNCs (synchronous cyclic, type %1)</source>
        <translation>每 %1 個 SYNC 送出一次（同步週期，類型 %1）</translation>
    </message>
    <message>
        <source>Applied at the next SYNC (synchronous, type %1)</source>
        <translation>在下一個 SYNC 套用（同步，類型 %1）</translation>
    </message>
    <message>
        <source>Sampled at SYNC, sent only when asked for (RTR-only synchronous, type 252)</source>
        <translation>在 SYNC 取樣，僅在被請求時送出（僅 RTR 同步，類型 252）</translation>
    </message>
    <message>
        <source>Sent only when asked for (RTR-only event-driven, type 253)</source>
        <translation>僅在被請求時送出（僅 RTR 事件觸發，類型 253）</translation>
    </message>
    <message>
        <source>Sent when a value changes and/or every event-timer period (event-driven, type %1)</source>
        <translation>值變化時和／或每個事件計時器週期送出（事件觸發，類型 %1）</translation>
    </message>
    <message>
        <source>Applied as soon as it arrives (event-driven, type %1)</source>
        <translation>收到後立即套用（事件觸發，類型 %1）</translation>
    </message>
    <message>
        <source>Reserved transmission type %1</source>
        <translation>保留的傳輸類型 %1</translation>
    </message>
</context>
<context>
    <name>ProjectProgram</name>
    <message>
        <source>Download the project&apos;s program</source>
        <translation>下載專案的程式</translation>
    </message>
    <message>
        <source>The project&apos;s program of node %1 is not there: %2</source>
        <translation>找不到專案中節點 %1 的程式：%2</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Decoding the PDOs with the assigned dictionaries</source>
        <translation>正在以指定的字典解碼 PDO</translation>
    </message>
    <message>
        <source>Fault reset (transition 15): clears the fault once its cause is removed. Sends controlword 6040h = 0000h, then 0080h (bit 7 rising). Expect Switch on disabled: fault bit 3 off, bit 6 on.</source>
        <translation>故障重置（轉換 15）：在故障原因排除後清除故障。送出控制字 6040h = 0000h，接著 0080h（位元 7 上升緣）。預期進入禁止啟動（Switch on disabled）：故障位元 3 為 0，位元 6 為 1。</translation>
    </message>
    <message>
        <source>Shutdown (transition 2): gets the drive ready, the motor stays without power. Sends 6040h = 0006h. Expect Ready to switch on: bits 0 and 5 on, bit 6 off.</source>
        <translation>關閉（Shutdown，轉換 2）：讓驅動器準備就緒，馬達仍不通電。送出 6040h = 0006h。預期進入準備啟動（Ready to switch on）：位元 0 與 5 為 1，位元 6 為 0。</translation>
    </message>
    <message>
        <source>Switch on (transition 3): switches the power stage on, the motor is not yet energised; needs main power. Sends 6040h = 0007h. Expect Switched on: bits 0, 1, 4 (voltage enabled) and 5 on.</source>
        <translation>啟動（Switch on，轉換 3）：開啟功率級，馬達尚未通電；需要主電源。送出 6040h = 0007h。預期進入已啟動（Switched on）：位元 0、1、4（電壓已啟用）與 5 為 1。</translation>
    </message>
    <message>
        <source>Enable operation (transition 4): energises the motor, which then holds its position and follows commands. Sends 6040h = 000Fh. Expect Operation enabled: bits 0, 1, 2 and 5 on.</source>
        <translation>運轉致能（Enable operation，轉換 4）：馬達通電，保持位置並依命令動作。送出 6040h = 000Fh。預期進入運轉致能（Operation enabled）：位元 0、1、2 與 5 為 1。</translation>
    </message>
    <message>
        <source>booting (boot-up)</source>
        <translation>開機中（boot-up）</translation>
    </message>
    <message>
        <source>stopped</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>running (operational)</source>
        <translation>運轉中（操作狀態）</translation>
    </message>
    <message>
        <source>ready (pre-operational)</source>
        <translation>就緒（預操作狀態）</translation>
    </message>
    <message>
        <source>seen</source>
        <translation>已偵測</translation>
    </message>
</context>
<context>
    <name>SdoGroupIndex</name>
    <message>
        <source>SDO read node %1 %2</source>
        <extracomment>Trace, one row per SDO transfer: %1 = node, %2 = object (&quot;6041:00 Statusword&quot;)</extracomment>
        <translation>SDO 讀取 節點 %1 %2</translation>
    </message>
    <message>
        <source>SDO write node %1 %2</source>
        <translation>SDO 寫入 節點 %1 %2</translation>
    </message>
    <message>
        <source>block</source>
        <translation>區塊</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>分段</translation>
    </message>
    <message>
        <source>expedited</source>
        <translation>加速</translation>
    </message>
    <message>
        <source>1 frame</source>
        <translation>1 個封包</translation>
    </message>
    <message>
        <source>%1 frames</source>
        <translation>%1 個封包</translation>
    </message>
    <message>
        <source>: aborted 0x%1 %2 (%3, %4)</source>
        <extracomment>%1 = abort code in hex, %2 = its meaning, %3 = expedited/segmented/block, %4 = &quot;3 frames&quot;</extracomment>
        <translation>：已中止 0x%1 %2（%3，%4）</translation>
    </message>
    <message>
        <source> (%1, %2 bytes, %3)</source>
        <extracomment>%1 = expedited/segmented/block, %2 = size, %3 = &quot;3 frames&quot;</extracomment>
        <translation>（%1，%2 位元組，%3）</translation>
    </message>
</context>
<context>
    <name>TraceFilter</name>
    <message>
        <source>filter: &apos;%1&apos; is not a node-ID (0-127)</source>
        <translation>篩選：「%1」不是節點 ID（0-127）</translation>
    </message>
    <message>
        <source>filter: &apos;node:&apos; needs node-IDs, e.g. node:5,6</source>
        <translation>篩選：「node:」需要節點 ID，例如 node:5,6</translation>
    </message>
    <message>
        <source>filter: unknown service &apos;%1&apos; (NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ SDO_RESP NMT_EC LSS_REQ LSS_RESP, or sdo, pdo)</source>
        <translation>篩選：未知的服務「%1」（NMT SYNC TIME EMCY TPDO1..4 RPDO1..4 SDO_REQ SDO_RESP NMT_EC LSS_REQ LSS_RESP，或 sdo、pdo）</translation>
    </message>
    <message>
        <source>filter: &apos;svc:&apos; needs service names, e.g. svc:sdo,emcy</source>
        <translation>篩選：「svc:」需要服務名稱，例如 svc:sdo,emcy</translation>
    </message>
    <message>
        <source>filter: &apos;%1&apos; is not a COB-ID or range in hex (e.g. 580-5FF)</source>
        <translation>篩選：「%1」不是十六進位的 COB-ID 或範圍（例如 580-5FF）</translation>
    </message>
    <message>
        <source>filter: &apos;id:&apos; needs COB-IDs in hex, e.g. id:580-5FF</source>
        <translation>篩選：「id:」需要十六進位的 COB-ID，例如 id:580-5FF</translation>
    </message>
    <message>
        <source>Grouping SDO transfers</source>
        <translation>正在將 SDO 傳輸分組</translation>
    </message>
    <message>
        <source>Filtering</source>
        <translation>篩選中</translation>
    </message>
</context>
<context>
    <name>TraceFind</name>
    <message>
        <source>Finding &apos;%1&apos;</source>
        <translation>正在尋找「%1」</translation>
    </message>
</context>
<context>
    <name>WizardButtons</name>
    <message>
        <source>&lt; &amp;Back</source>
        <extracomment>A wizard&apos;s button to the previous step</extracomment>
        <translation>&lt; 上一步(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Next &gt;</source>
        <extracomment>A wizard&apos;s button to the next step</extracomment>
        <translation>下一步(&amp;N) &gt;</translation>
    </message>
</context>
<context>
    <name>WizardFramesPane</name>
    <message>
        <source>Time (s)</source>
        <translation>時間（秒）</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Meaning</source>
        <translation>含義</translation>
    </message>
</context>
<context>
    <name>WizardMenu</name>
    <message>
        <source>Baud rate and node-ID…</source>
        <translation>鮑率與節點 ID…</translation>
    </message>
    <message>
        <source>CiA 402 enable step-through…</source>
        <translation>CiA 402 逐步致能…</translation>
    </message>
    <message>
        <source>PDO mapping…</source>
        <translation>PDO 映射…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ApplyDialog</name>
    <message>
        <source>Apply the project</source>
        <translation>套用專案</translation>
    </message>
    <message>
        <source>&amp;Apply</source>
        <translation>套用(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Store in the drives…</source>
        <translation>儲存到驅動器(&amp;S)…</translation>
    </message>
    <message>
        <source>Save &amp;report…</source>
        <translation>儲存報告(&amp;R)…</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only).</source>
        <translation>請先連線到機台的匯流排（非僅監聽）。</translation>
    </message>
    <message>
        <source>Reading the drives&apos; values (dry run)…</source>
        <translation>正在讀取驅動器的值（模擬執行）…</translation>
    </message>
    <message>
        <source>Dry run: the SDO writes per node</source>
        <translation>模擬執行：各節點的 SDO 寫入</translation>
    </message>
    <message>
        <source>The drives already hold the project&apos;s values: nothing to write.</source>
        <translation>驅動器已是專案的值：不需寫入。</translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) to write to %1 node(s). Check the writes below, then Apply.</source>
        <translation>
            <numerusform>要寫入 %1 個節點的 %n 個物件。請檢查下列寫入，再按「套用」。</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Write %n object(s) to the drives as listed? The first refused write stops; that node&apos;s old values are put back.</source>
        <translation>
            <numerusform>要依清單把 %n 個物件寫入驅動器嗎？第一個被拒絕的寫入會停止，該節點的舊值會寫回。</numerusform>
        </translation>
    </message>
    <message>
        <source>Writing…</source>
        <translation>正在寫入…</translation>
    </message>
    <message>
        <source>Node %1 is a new drive (serial number 0x%2): the project now expects it.</source>
        <translation>節點 %1 是新的驅動器（序號 0x%2）：專案現在以它為準。</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <source>The project was applied. The drives lose these values at power off unless they are stored.</source>
        <translation>專案已套用。除非儲存，驅動器斷電後會失去這些值。</translation>
    </message>
    <message>
        <source>The project was not applied in full: see the result below.</source>
        <translation>專案未完整套用：請見下方結果。</translation>
    </message>
    <message>
        <source>Store in the drives</source>
        <translation>儲存到驅動器</translation>
    </message>
    <message numerus="yes">
        <source>Save all parameters in the non-volatile memory of %n drive(s) (1010h:01 = &quot;save&quot;)?</source>
        <translation>
            <numerusform>要把全部參數儲存到 %n 台驅動器的非揮發性記憶體嗎（1010h:01 = &quot;save&quot;）？</numerusform>
        </translation>
    </message>
    <message>
        <source>stored: %1</source>
        <translation>已儲存：%1</translation>
    </message>
    <message>
        <source>NOT stored: %1</source>
        <translation>未儲存：%1</translation>
    </message>
    <message>
        <source>The parameters are stored in the drives.</source>
        <translation>參數已儲存在驅動器中。</translation>
    </message>
    <message>
        <source>A drive did not store its parameters: see below.</source>
        <translation>有驅動器未儲存參數：請見下方。</translation>
    </message>
    <message>
        <source>Save report</source>
        <translation>儲存報告</translation>
    </message>
    <message>
        <source>Text files (*.txt);;All files (*)</source>
        <translation>文字檔 (*.txt);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>Report saved to %1</source>
        <translation>報告已儲存到 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::BusLossAdvice</name>
    <message>
        <source>NMT state unknown</source>
        <translation>NMT 狀態未知</translation>
    </message>
    <message>
        <source>NMT: %1</source>
        <translation>NMT：%1</translation>
    </message>
    <message>
        <source>Bus lost (%1). The wizard stopped: nothing more can be sent to node %2.</source>
        <translation>匯流排中斷（%1）。精靈已停止：無法再向節點 %2 傳送任何訊息。</translation>
    </message>
    <message>
        <source>Last known state: %1, %2.</source>
        <translation>最後已知狀態：%1，%2。</translation>
    </message>
    <message>
        <source>The drive may still be enabled (and moving, if it was): only its own communication-loss reaction (6007h) or heartbeat consumer (1016h) stops it.</source>
        <translation>驅動器可能仍處於致能狀態（若原本在運轉，也可能仍在運轉）：只有它自身的通訊中斷反應（6007h）或心跳消費者（1016h）才會讓它停下。</translation>
    </message>
    <message>
        <source>The drive was not enabled by this wizard; it should still be in that state.</source>
        <translation>此精靈沒有將驅動器致能；它應仍保持原來的狀態。</translation>
    </message>
    <message>
        <source>Check at the drive (display, enable LED, brake) before going near the machine. CoScope reconnects by itself; press “Read state” when the bus is back.</source>
        <translation>靠近機台前，請先在驅動器上確認（顯示器、致能指示燈、煞車）。CoScope 會自動重新連線；匯流排恢復後請按「讀取狀態」。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) during step %2 of %3. The steps before it were sent; this one may or may not have reached the device, nothing after it was sent. The device may be half-configured (a PDO left disabled, a new node-ID or bit rate stored but not applied). When the bus is back, read the objects of this script back before running it again.</source>
        <translation>已停止：第 %2 步（共 %3 步）執行時匯流排中斷（%1）。之前的步驟都已送出；這一步不一定已送達裝置，之後的步驟都沒有送出。裝置可能只設定了一半（某個 PDO 仍被停用，或新的節點 ID、鮑率已儲存但尚未生效）。匯流排恢復後，請先讀回此腳本涉及的物件，再重新執行。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) while applying %2 of node %3 (last known %4). The PDO may be left disabled (COB-ID bit 31 set) with its mapping half written, and the node pre-operational. When the bus is back, read %2 back (Choose page) and apply again; the drive&apos;s own communication-loss reaction decides what it does meanwhile.</source>
        <translation>已停止：套用節點 %3 的 %2 時匯流排中斷（%1）（最後已知：%4）。該 PDO 可能仍被停用（COB-ID 第 31 位元為 1），映射只寫入一半，節點停在預操作狀態。匯流排恢復後，請讀回 %2（選擇頁）並重新套用；在此期間驅動器如何動作，取決於它自身的通訊中斷反應。</translation>
    </message>
    <message>
        <source>Stopped: bus lost (%1) during the change of node %2 (last known %3). The device may have taken the new node-ID or bit rate, stored it without applying it, or kept the old one. When the bus is back, scan (and if nothing answers, connect at the other bit rate) to see where the device is before changing anything else.</source>
        <translation>已停止：變更節點 %2 時匯流排中斷（%1）（最後已知：%3）。裝置可能已採用新的節點 ID 或鮑率、已儲存但尚未生效，或仍保留舊值。匯流排恢復後，請先掃描（若無回應，改用另一個鮑率連線），確認裝置目前的設定，再做其他變更。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::BusStatusBar</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Restart controller</source>
        <translation>重新啟動控制器</translation>
    </message>
    <message>
        <source>The controller went bus-off and sends nothing; restart it (check wiring, termination and bit rate first)</source>
        <translation>控制器已進入匯流排關閉（bus-off），不再傳送任何封包；請重新啟動它（請先檢查配線、終端電阻與位元速率）</translation>
    </message>
    <message>
        <source>No source</source>
        <translation>無來源</translation>
    </message>
    <message>
        <source>Offline</source>
        <translation>離線</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation>%L1 個封包</translation>
    </message>
    <message>
        <source> · listen-only</source>
        <translation> · 僅監聽</translation>
    </message>
    <message>
        <source>%L1 frames/s</source>
        <translation>%L1 封包/秒</translation>
    </message>
    <message>
        <source>load %1 %</source>
        <translation>負載 %1 %</translation>
    </message>
    <message>
        <source>Estimated from frame lengths with worst-case bit stuffing at %1 bit/s</source>
        <translation>依封包長度估算，以最壞情況的位元填充、%1 bit/s 計算</translation>
    </message>
    <message>
        <source>dropped %L1</source>
        <translation>遺失 %L1</translation>
    </message>
    <message>
        <source>errors %L1</source>
        <translation>錯誤 %L1</translation>
    </message>
    <message>
        <source>error active</source>
        <translation>錯誤主動</translation>
    </message>
    <message>
        <source>error warning</source>
        <translation>錯誤警告</translation>
    </message>
    <message>
        <source>error passive</source>
        <translation>錯誤被動</translation>
    </message>
    <message>
        <source>bus-off</source>
        <translation>匯流排關閉</translation>
    </message>
    <message>
        <source> · TEC %1 REC %2</source>
        <translation> · TEC %1 REC %2</translation>
    </message>
    <message>
        <source>CAN controller state from the last error frame (transmit / receive error counters)</source>
        <translation>取自最近一個錯誤封包的 CAN 控制器狀態（傳送／接收錯誤計數器）</translation>
    </message>
    <message>
        <source>Controller restarted after bus-off</source>
        <translation>控制器已在匯流排關閉後重新啟動</translation>
    </message>
    <message>
        <source>Restart after bus-off failed: %1</source>
        <translation>匯流排關閉後重新啟動失敗：%1</translation>
    </message>
    <message>
        <source>Last restart failed: %1</source>
        <translation>上次重新啟動失敗：%1</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已關閉</translation>
    </message>
    <message>
        <source>opening</source>
        <translation>開啟中</translation>
    </message>
    <message>
        <source>open</source>
        <translation>已開啟</translation>
    </message>
    <message>
        <source>error</source>
        <translation>錯誤</translation>
    </message>
    <message>
        <source>lost, retrying now</source>
        <translation>已中斷，正在重試</translation>
    </message>
    <message>
        <source>lost, retrying in %1 s</source>
        <translation>已中斷，%1 秒後重試</translation>
    </message>
    <message>
        <source>Adapter lost: %1. The trace keeps everything; CoScope reopens the bus when it is back (Disconnect stops trying).</source>
        <translation>轉接器中斷：%1。追蹤保留所有已收到的封包；轉接器恢復後 CoScope 會重新開啟匯流排（按「中斷連線」即停止重試）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CaptureSettingsDialog</name>
    <message>
        <source>Capture settings</source>
        <translation>擷取設定</translation>
    </message>
    <message>
        <source>Automatic (%1)</source>
        <translation>自動（%1）</translation>
    </message>
    <message>
        <source> days</source>
        <translation> 天</translation>
    </message>
    <message>
        <source>Trace memory budget:</source>
        <translation>追蹤記憶體上限：</translation>
    </message>
    <message>
        <source>Keep capture journals for:</source>
        <translation>擷取日誌保留時間：</translation>
    </message>
    <message>
        <source>Keep capture journals up to:</source>
        <translation>擷取日誌保留總量上限：</translation>
    </message>
    <message>
        <source>Capture journals are kept in %1. Older ones are removed at start and when these settings change; a journal being written or not yet offered for reopening is never removed.</source>
        <translation>擷取日誌保存在 %1。較舊的日誌會在啟動時及這些設定變更時移除；正在寫入或尚未提供重新開啟的日誌絕不會被移除。</translation>
    </message>
    <message>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <source>The trace keeps at most this much in memory; older frames are read back from the capture journal when needed. 0 = automatic: a quarter of the memory, at most 4 GiB.</source>
        <translation>追蹤在記憶體中最多保留這麼多；較舊的封包在需要時從擷取日誌讀回。0 = 自動：記憶體的四分之一，最多 4 GiB。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CompareDialog</name>
    <message>
        <source>Machine and project</source>
        <translation>機台與專案</translation>
    </message>
    <message>
        <source>&amp;Only differences</source>
        <translation>只顯示差異(&amp;O)</translation>
    </message>
    <message>
        <source>&amp;Compare again</source>
        <translation>再次比較(&amp;C)</translation>
    </message>
    <message>
        <source>Export &amp;HTML…</source>
        <translation>匯出 &amp;HTML…</translation>
    </message>
    <message>
        <source>Export CS&amp;V…</source>
        <translation>匯出 CS&amp;V…</translation>
    </message>
    <message>
        <source>&amp;Replace drive…</source>
        <translation>更換驅動器(&amp;R)…</translation>
    </message>
    <message>
        <source>&amp;Apply the project…</source>
        <translation>套用專案(&amp;A)…</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only): the comparison reads the drives.</source>
        <translation>請先連線到機台的匯流排（非僅監聽）：比較會讀取驅動器。</translation>
    </message>
    <message>
        <source>Scanning the bus and reading the drives…</source>
        <translation>正在掃描匯流排並讀取驅動器…</translation>
    </message>
    <message>
        <source>The machine is as in the project.</source>
        <translation>機台與專案一致。</translation>
    </message>
    <message numerus="yes">
        <source>%n object(s) differ; %1 node(s) not as in the project.</source>
        <translation>
            <numerusform>%n 個物件不同；%1 個節點與專案不符。</numerusform>
        </translation>
    </message>
    <message>
        <source>Export comparison as HTML</source>
        <translation>將比較結果匯出為 HTML</translation>
    </message>
    <message>
        <source>Export comparison as CSV</source>
        <translation>將比較結果匯出為 CSV</translation>
    </message>
    <message>
        <source>HTML files (*.html)</source>
        <translation>HTML 檔案 (*.html)</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 檔案 (*.csv)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>無法寫入 %1：%2</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>已匯出到 %1</translation>
    </message>
    <message>
        <source>Replace drive</source>
        <translation>更換驅動器</translation>
    </message>
    <message>
        <source>Node %1 is another drive of the same type. Write the project&apos;s configuration of node %1 to it? The writes are shown first.</source>
        <translation>節點 %1 是另一台同型驅動器。要把專案中節點 %1 的設定寫入它嗎？會先列出寫入內容。</translation>
    </message>
    <message>
        <source>Open the node-ID wizard</source>
        <translation>開啟節點 ID 精靈</translation>
    </message>
    <message>
        <source>Download the project&apos;s &amp;program…</source>
        <translation>下載專案的程式(&amp;P)…</translation>
    </message>
    <message>
        <source>Load the program (firmware) the project names for the selected node: CiA 302-3 program download</source>
        <translation>為選取的節點載入專案指定的程式（韌體）：CiA 302-3 程式下載</translation>
    </message>
    <message>
        <source>Node %1 does not answer, and node %2 is a drive of the same type that the project does not have (a new drive at its factory node-ID?). Give it node-ID %1 with the node-ID wizard, then write the project&apos;s configuration of node %1 to it and compare again?</source>
        <translation>節點 %1 沒有回應，而節點 %2 是專案中沒有的同型驅動器（出廠節點 ID 的新驅動器？）。要以節點 ID 精靈將它設為節點 ID %1，再寫入專案中節點 %1 的設定並重新比較嗎？</translation>
    </message>
    <message>
        <source>Node %1 does not answer. If a new drive of the same type is on the bus at another node-ID or without one, find it in the node-ID wizard (scan, or find a device without node-ID by LSS) and give it node-ID %1; then the project&apos;s configuration of node %1 is written to it and the machine compared again.</source>
        <translation>節點 %1 沒有回應。若匯流排上有一台使用其他節點 ID 或沒有節點 ID 的同型新驅動器，請在節點 ID 精靈中找到它（掃描，或以 LSS 尋找沒有節點 ID 的裝置）並設為節點 ID %1；之後會寫入專案中節點 %1 的設定並重新比較機台。</translation>
    </message>
    <message>
        <source>Replacing node %1: give the new drive node-ID %1 in the node-ID wizard.</source>
        <translation>正在更換節點 %1：請在節點 ID 精靈中將新驅動器設為節點 ID %1。</translation>
    </message>
    <message>
        <source>The new drive answers at node %1: the project&apos;s configuration of node %1 is written to it next.</source>
        <translation>新驅動器已在節點 %1 回應：接著將寫入專案中節點 %1 的設定。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::CompareModel</name>
    <message>
        <source>same</source>
        <translation>相同</translation>
    </message>
    <message>
        <source>replaced (another serial number)</source>
        <translation>已更換（序號不同）</translation>
    </message>
    <message>
        <source>different device</source>
        <translation>不同的裝置</translation>
    </message>
    <message>
        <source>missing</source>
        <translation>缺少</translation>
    </message>
    <message>
        <source>not in project</source>
        <translation>不在專案中</translation>
    </message>
    <message>
        <source>differs</source>
        <translation>不同</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>無法讀取</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <source>Project</source>
        <translation>專案</translation>
    </message>
    <message>
        <source>Drive</source>
        <translation>驅動器</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>預設值</translation>
    </message>
    <message>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <source>Software version</source>
        <translation>軟體版本</translation>
    </message>
    <message>
        <source>Software identification</source>
        <translation>軟體識別碼</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConnectDialog</name>
    <message>
        <source>Connect to a CAN bus</source>
        <translation>連線到 CAN 匯流排</translation>
    </message>
    <message>
        <source>(recent connections)</source>
        <translation>（最近的連線）</translation>
    </message>
    <message>
        <source>Recent:</source>
        <translation>最近：</translation>
    </message>
    <message>
        <source>Virtual drives (sim://)</source>
        <translation>虛擬驅動器（sim://）</translation>
    </message>
    <message>
        <source>socketcand server (remote CAN)</source>
        <translation>socketcand 伺服器（遠端 CAN）</translation>
    </message>
    <message>
        <source>Qt CAN plugin: %1</source>
        <translation>Qt CAN 外掛：%1</translation>
    </message>
    <message>
        <source>Replay a log file</source>
        <translation>重播記錄檔</translation>
    </message>
    <message>
        <source>Backend:</source>
        <translation>後端：</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>裝置：</translation>
    </message>
    <message>
        <source>No CAN interfaces found. A virtual one for trying: &lt;tt&gt;sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up&lt;/tt&gt;. A real adapter: &lt;tt&gt;sudo ip link set can0 up type can bitrate 500000&lt;/tt&gt;. Then choose the backend again.</source>
        <translation>找不到 CAN 介面。可先建立一個虛擬介面試用：&lt;tt&gt;sudo modprobe vcan; sudo ip link add dev vcan0 type vcan; sudo ip link set vcan0 up&lt;/tt&gt;。實體轉接器：&lt;tt&gt;sudo ip link set can0 up type can bitrate 500000&lt;/tt&gt;。然後再選一次後端。</translation>
    </message>
    <message>
        <source>Bring up</source>
        <translation>啟用介面</translation>
    </message>
    <message>
        <source>Host:</source>
        <translation>主機：</translation>
    </message>
    <message>
        <source>Port:</source>
        <translation>連接埠：</translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation>通道：</translation>
    </message>
    <message>
        <source>Virtual drives on the in-process bus:</source>
        <translation>程序內匯流排上的虛擬驅動器：</translation>
    </message>
    <message>
        <source>Drive (dictionary)</source>
        <translation>驅動器（字典）</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <source>Log to replay</source>
        <translation>要重播的記錄檔</translation>
    </message>
    <message>
        <source>Log:</source>
        <translation>記錄檔：</translation>
    </message>
    <message>
        <source>1×</source>
        <translation>1×</translation>
    </message>
    <message>
        <source>10×</source>
        <translation>10×</translation>
    </message>
    <message>
        <source>100×</source>
        <translation>100×</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>盡可能快</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>循環播放</translation>
    </message>
    <message>
        <source>Speed:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>(adapter setting)</source>
        <translation>（轉接器設定）</translation>
    </message>
    <message>
        <source>%L1 kbit/s</source>
        <translation>%L1 kbit/s</translation>
    </message>
    <message>
        <source>Bit rate:</source>
        <translation>鮑率：</translation>
    </message>
    <message>
        <source>CAN FD</source>
        <translation>CAN FD</translation>
    </message>
    <message>
        <source>data %L1 Mbit/s</source>
        <translation>資料段 %L1 Mbit/s</translation>
    </message>
    <message>
        <source>Listen-only (never transmit)</source>
        <translation>僅監聽（絕不傳送）</translation>
    </message>
    <message>
        <source>Type or paste a bus URL, e.g. socketcan://can0?bitrate=500000</source>
        <translation>輸入或貼上匯流排 URL，例如 socketcan://can0?bitrate=500000</translation>
    </message>
    <message>
        <source>URL:</source>
        <translation>URL：</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>連線</translation>
    </message>
    <message>
        <source>Listed by the plugin without finding an adapter</source>
        <translation>外掛列出了此項，但未找到轉接器</translation>
    </message>
    <message>
        <source>Could not bring the interface up: %1</source>
        <translation>無法啟用介面：%1</translation>
    </message>
    <message>
        <source>%1 is down</source>
        <translation>%1 已停用</translation>
    </message>
    <message>
        <source>%1 is up (virtual CAN)</source>
        <translation>%1 已啟用（虛擬 CAN）</translation>
    </message>
    <message>
        <source>%1 is up at %L2 kbit/s</source>
        <translation>%1 已啟用，鮑率 %L2 kbit/s</translation>
    </message>
    <message>
        <source>%1 is up</source>
        <translation>%1 已啟用</translation>
    </message>
    <message>
        <source>, CAN FD data %L1 Mbit/s</source>
        <translation>，CAN FD 資料段 %L1 Mbit/s</translation>
    </message>
    <message>
        <source>, controller in error warning (TEC %1, REC %2)</source>
        <translation>，控制器處於錯誤警告（TEC %1，REC %2）</translation>
    </message>
    <message>
        <source>, controller error passive (TEC %1, REC %2)</source>
        <translation>，控制器處於錯誤被動（TEC %1，REC %2）</translation>
    </message>
    <message>
        <source>, controller is bus-off: check wiring, termination and bit rate</source>
        <translation>，控制器已匯流排關閉：請檢查配線、終端電阻與鮑率</translation>
    </message>
    <message>
        <source>, controller stopped</source>
        <translation>，控制器已停止</translation>
    </message>
    <message>
        <source>Unverified: the %1 plugin lists %2 without finding an adapter; connecting shows whether one is there.</source>
        <translation>未確認：%1 外掛列出了 %2，但未找到轉接器；連線後即可知道轉接器是否存在。</translation>
    </message>
    <message>
        <source>To change its bit rate, run:</source>
        <translation>要變更其鮑率，請執行：</translation>
    </message>
    <message>
        <source>Bring it up with:</source>
        <translation>以下列指令啟用：</translation>
    </message>
    <message>
        <source>Change bit rate now</source>
        <translation>立即變更鮑率</translation>
    </message>
    <message>
        <source>Bring up now</source>
        <translation>立即啟用</translation>
    </message>
    <message>
        <source>CoScope runs without the right to configure network interfaces: run the command above in a terminal</source>
        <translation>CoScope 沒有設定網路介面的權限：請在終端機中執行上面的指令</translation>
    </message>
    <message>
        <source>Choose at least one virtual drive</source>
        <translation>請至少選擇一台虛擬驅動器</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ConsoleDock</name>
    <message>
        <source>Console</source>
        <translation>主控台</translation>
    </message>
</context>
<context>
    <name>coscope::gui::DcfApplyDialog</name>
    <message>
        <source>Apply DCF to node %1</source>
        <translation>將 DCF 套用到節點 %1</translation>
    </message>
    <message>
        <source>Nothing to write: every value of %1 is already on node %2 or cannot be written (%3 entries, listed below).</source>
        <translation>沒有需要寫入的項目：%1 的每個值都已與節點 %2 相同，或無法寫入（%3 個項目，列於下方）。</translation>
    </message>
    <message>
        <source>Write %1 object(s) from &lt;b&gt;%2&lt;/b&gt; to &lt;b&gt;node %3&lt;/b&gt; over SDO? Each write is sent once; a refused write is reported and the others continue. %4 entries are not written (greyed).</source>
        <translation>要透過 SDO 將 &lt;b&gt;%2&lt;/b&gt; 的 %1 個物件寫入 &lt;b&gt;節點 %3&lt;/b&gt; 嗎？每筆寫入只送出一次；被拒絕的寫入會回報，其餘照常進行。有 %4 個項目不會寫入（灰色顯示）。</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <source>Write</source>
        <translation>寫入</translation>
    </message>
    <message>
        <source>Node now / result</source>
        <translation>節點目前值／結果</translation>
    </message>
    <message>
        <source>(not read)</source>
        <translation>（未讀取）</translation>
    </message>
    <message>
        <source>not written: %1</source>
        <translation>未寫入：%1</translation>
    </message>
    <message>
        <source>Write %1 object(s)</source>
        <translation>寫入 %1 個物件</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已寫入</translation>
    </message>
    <message>
        <source>Node %1: %2 of %3 write(s) done, %4 refused%5.</source>
        <translation>節點 %1：完成 %2／%3 筆寫入，%4 筆被拒絕%5。</translation>
    </message>
    <message>
        <source>, cancelled before the rest</source>
        <translation>，其餘在取消前未送出</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402FramesTabs</name>
    <message>
        <source>Frames (requests and responses)</source>
        <translation>封包（請求與回應）</translation>
    </message>
    <message>
        <source>Dry run (what will be sent)</source>
        <translation>模擬執行（將送出的內容）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402HomingBox</name>
    <message>
        <source>Method (6098h):</source>
        <translation>方式（6098h）：</translation>
    </message>
    <message>
        <source>Speed, search for switch (6099h:01):</source>
        <translation>速度，搜尋開關（6099h:01）：</translation>
    </message>
    <message>
        <source>Speed, search for zero (6099h:02):</source>
        <translation>速度，搜尋零點（6099h:02）：</translation>
    </message>
    <message>
        <source>Acceleration (609Ah):</source>
        <translation>加減速度（609Ah）：</translation>
    </message>
    <message>
        <source>Home offset (607Ch):</source>
        <translation>原點偏移（607Ch）：</translation>
    </message>
    <message>
        <source>Start homing…</source>
        <translation>開始原點復歸…</translation>
    </message>
    <message>
        <source>Asks first. Then sets homing mode (6060h = 6), writes the values above, enables the drive and starts homing (6040h = 001Fh).</source>
        <translation>先詢問。接著設定原點復歸模式（6060h = 6）、寫入上方的值、讓驅動器致能並開始原點復歸（6040h = 001Fh）。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Halts the homing on the drive&apos;s ramp (6040h = 010Fh); the drive stays enabled.</source>
        <translation>依驅動器的斜坡暫停原點復歸（6040h = 010Fh）；驅動器保持致能。</translation>
    </message>
    <message>
        <source>home found</source>
        <translation>已找到原點</translation>
    </message>
    <message>
        <source>Not started.</source>
        <translation>尚未開始。</translation>
    </message>
    <message>
        <source>The homing&apos;s motion shows here</source>
        <translation>原點復歸的運動顯示於此</translation>
    </message>
    <message>
        <source>Type a method number (-128 to 127) or choose one.</source>
        <translation>輸入方式編號（-128 至 127）或從清單選擇。</translation>
    </message>
    <message>
        <source>Not a homing method of the %1 (it has %2): it would be refused.</source>
        <translation>不是 %1 的原點復歸方式（它有 %2）：會被拒絕。</translation>
    </message>
    <message>
        <source>Not a CiA 402-2 homing method; the drive&apos;s own manual may define it.</source>
        <translation>不是 CiA 402-2 的原點復歸方式；驅動器自己的手冊可能有定義。</translation>
    </message>
    <message>
        <source>(The drive&apos;s dictionary is not known: CiA 402-2&apos;s methods are listed.)</source>
        <translation>（不知道驅動器的字典：列出的是 CiA 402-2 的方式。）</translation>
    </message>
    <message>
        <source>Starting: homing mode, values, enable…</source>
        <translation>啟動中：原點復歸模式、數值、致能…</translation>
    </message>
    <message>
        <source>%1 s: statusword %2, position %3, velocity %4</source>
        <translation>%1 秒：狀態字 %2，位置 %3，速度 %4</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402ModeBox</name>
    <message>
        <source>Mode of operation (6060h / 6061h)</source>
        <translation>操作模式（6060h / 6061h）</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <source>Set and verify</source>
        <translation>設定並驗證</translation>
    </message>
    <message>
        <source>Mode:</source>
        <translation>模式：</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): not read</source>
        <translation>驅動器顯示（6061h）：未讀取</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1</source>
        <translation>驅動器顯示（6061h）：%1</translation>
    </message>
    <message>
        <source>Shown by the drive (6061h): %1 ✓</source>
        <translation>驅動器顯示（6061h）：%1 ✓</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402MotionPlot</name>
    <message>
        <source>position 6064h</source>
        <translation>位置 6064h</translation>
    </message>
    <message>
        <source>position 6064h: %1</source>
        <translation>位置 6064h：%1</translation>
    </message>
    <message>
        <source>velocity 606Ch</source>
        <translation>速度 606Ch</translation>
    </message>
    <message>
        <source>velocity 606Ch: %1</source>
        <translation>速度 606Ch：%1</translation>
    </message>
    <message>
        <source>The test move&apos;s motion shows here</source>
        <translation>測試運轉的運動曲線顯示於此</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402PositionMoveBox</name>
    <message>
        <source>Relative (6040h bit 6)</source>
        <translation>相對（6040h 位元 6）</translation>
    </message>
    <message>
        <source>Target (607Ah):</source>
        <translation>目標（607Ah）：</translation>
    </message>
    <message>
        <source>Profile velocity (6081h):</source>
        <translation>輪廓速度（6081h）：</translation>
    </message>
    <message>
        <source>Acceleration (6083h):</source>
        <translation>輪廓加速度（6083h）：</translation>
    </message>
    <message>
        <source>Deceleration (6084h):</source>
        <translation>輪廓減速度（6084h）：</translation>
    </message>
    <message>
        <source>Arm position move…</source>
        <translation>準備位置移動…</translation>
    </message>
    <message>
        <source>Hold to move</source>
        <translation>按住移動</translation>
    </message>
    <message>
        <source>The motor moves only while this button is held down; releasing it halts the motor (6040h bit 8).</source>
        <translation>只有按住此按鈕時馬達才會移動；放開即暫停馬達（6040h 位元 8）。</translation>
    </message>
    <message>
        <source>6040h bit 4: new set-point</source>
        <translation>6040h 位元 4：新設定點</translation>
    </message>
    <message>
        <source>6041h bit 12: set-point acknowledge</source>
        <translation>6041h 位元 12：設定點確認</translation>
    </message>
    <message>
        <source>6041h bit 10: target reached</source>
        <translation>6041h 位元 10：到達目標</translation>
    </message>
    <message>
        <source>6041h bit 13: following error</source>
        <translation>6041h 位元 13：追隨誤差</translation>
    </message>
    <message>
        <source>The move&apos;s motion shows here</source>
        <translation>移動的運動顯示於此</translation>
    </message>
    <message>
        <source>move by %1 (relative, 607Ah = %2) at up to %3 (6081h)</source>
        <translation>移動 %1（相對，607Ah = %2），速度最高 %3（6081h）</translation>
    </message>
    <message>
        <source>move to position %1 (absolute, 607Ah = %2) at up to %3 (6081h)</source>
        <translation>移動到位置 %1（絕對，607Ah = %2），速度最高 %3（6081h）</translation>
    </message>
    <message>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <source>%1 of %2 → %3</source>
        <translation>%1（%2 → %3）</translation>
    </message>
    <message>
        <source>Set-point handshake: %1 new set-point (bit 4 = 1) → %2 acknowledged (bit 12), bit 4 = 0 → %3 target reached (bit 10)</source>
        <translation>設定點交握：%1 新設定點（位元 4 = 1）→ %2 已確認（位元 12），位元 4 = 0 → %3 到達目標（位元 10）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StateDiagram</name>
    <message>
        <source>State not read yet</source>
        <translation>尚未讀取狀態</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StatusPanel</name>
    <message>
        <source>Statusword (6041h): not read</source>
        <translation>狀態字（6041h）：未讀取</translation>
    </message>
    <message>
        <source>On: </source>
        <translation>開：</translation>
    </message>
    <message>
        <source>Off: </source>
        <translation>關：</translation>
    </message>
    <message>
        <source>Statusword (6041h) = %1 — %2</source>
        <translation>狀態字（6041h）= %1 — %2</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402StepBar</name>
    <message>
        <source>Step through — one button per transition</source>
        <translation>逐步執行 — 每個狀態轉換一個按鈕</translation>
    </message>
    <message>
        <source>1  Fault reset</source>
        <translation>1  故障重置</translation>
    </message>
    <message>
        <source>2  Shutdown</source>
        <translation>2  關閉（Shutdown）</translation>
    </message>
    <message>
        <source>3  Switch on</source>
        <translation>3  啟動（Switch on）</translation>
    </message>
    <message>
        <source>4  Enable operation…</source>
        <translation>4  運轉致能（Enable operation）…</translation>
    </message>
    <message>
        <source>The drive is enabled (Operation enabled). Choose a mode and try a test move, or press Disable.</source>
        <translation>驅動器已致能（Operation enabled）。請選擇模式並試做測試運轉，或按「停用」。</translation>
    </message>
    <message>
        <source>Quick stop is active: press Disable to leave it (Disable voltage, transition 12).</source>
        <translation>Quick Stop 已啟動：請按「停用」離開（Disable voltage，轉換 12）。</translation>
    </message>
    <message>
        <source>Next: %1</source>
        <translation>下一步：%1</translation>
    </message>
    <message>
        <source>The drive is in %1; wait for it to settle, then read the state again.</source>
        <translation>驅動器處於 %1；請等它穩定後再讀取一次狀態。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402TestMoveBox</name>
    <message>
        <source>Test move (optional, small limits)</source>
        <translation>測試運轉（選用，小範圍限制）</translation>
    </message>
    <message>
        <source>Jog (profile velocity, 60FFh)</source>
        <translation>寸動（profile velocity，60FFh）</translation>
    </message>
    <message>
        <source>Short move (profile position, 607Ah relative)</source>
        <translation>短距移動（profile position，607Ah 相對）</translation>
    </message>
    <message>
        <source>Kind:</source>
        <translation>類型：</translation>
    </message>
    <message>
        <source>Velocity:</source>
        <translation>速度：</translation>
    </message>
    <message>
        <source>Distance:</source>
        <translation>距離：</translation>
    </message>
    <message>
        <source> ms max</source>
        <translation> ms 上限</translation>
    </message>
    <message>
        <source>Time limit:</source>
        <translation>時間上限：</translation>
    </message>
    <message>
        <source>Arm test move…</source>
        <translation>準備測試運轉…</translation>
    </message>
    <message>
        <source>Hold to run</source>
        <translation>按住運轉</translation>
    </message>
    <message>
        <source>The motor moves only while this button is held down; releasing it stops the motor.</source>
        <translation>只有按住此按鈕時馬達才會運轉；放開即停止馬達。</translation>
    </message>
    <message>
        <source>turn at %1 (profile velocity, 60FFh = %2)</source>
        <translation>以 %1 轉動（profile velocity，60FFh = %2）</translation>
    </message>
    <message>
        <source>move %1 at up to %2 (profile position, relative: 607Ah = %3, 6081h = %4)</source>
        <translation>移動 %1，速度最高 %2（profile position，相對：607Ah = %3，6081h = %4）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Ds402Wizard</name>
    <message>
        <source>CiA 402 enable step-through</source>
        <translation>CiA 402 逐步致能</translation>
    </message>
    <message>
        <source>connection lost</source>
        <translation>連線中斷</translation>
    </message>
    <message>
        <source>Connection lost (bus %1). The drive was told to disable if the bus still accepted it; otherwise its own communication-loss reaction (6007h) applies. Check the drive.</source>
        <translation>連線中斷（匯流排 %1）。若匯流排仍可傳送，已通知驅動器停用；否則由驅動器自身的通訊中斷處理（6007h）決定。請檢查驅動器。</translation>
    </message>
    <message>
        <source>error</source>
        <translation>錯誤</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>已關閉</translation>
    </message>
    <message>
        <source>The connection changed. Choose the drive again.</source>
        <translation>連線已變更。請重新選擇驅動器。</translation>
    </message>
    <message>
        <source>Listen-only connection: this wizard is disabled because it would have to send (SDO to 6040h/6041h).</source>
        <translation>僅監聽連線：此精靈必須傳送（對 6040h/6041h 的 SDO），因此已停用。</translation>
    </message>
    <message>
        <source>wizard destroyed</source>
        <translation>精靈已銷毀</translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation>驅動器（節點）：</translation>
    </message>
    <message>
        <source>Read state</source>
        <translation>讀取狀態</translation>
    </message>
    <message>
        <source>Drive state (CiA 402 state machine)</source>
        <translation>驅動器狀態（CiA 402 狀態機）</translation>
    </message>
    <message>
        <source>Statusword bits</source>
        <translation>狀態字位元</translation>
    </message>
    <message>
        <source>Saved %1; replay it with: coscope-cli script run BUS %1</source>
        <translation>已儲存 %1；重播指令：coscope-cli script run BUS %1</translation>
    </message>
    <message>
        <source>Quick stop</source>
        <translation>快速停止</translation>
    </message>
    <message>
        <source>Brakes on the drive&apos;s quick stop ramp (6040h = 0002h).</source>
        <translation>依驅動器的 Quick Stop 減速曲線煞停（6040h = 0002h）。</translation>
    </message>
    <message>
        <source>Disable</source>
        <translation>停用</translation>
    </message>
    <message>
        <source>Removes power from the motor: Shutdown then Disable voltage (6040h = 0006h, 0000h).</source>
        <translation>切斷馬達電源：先 Shutdown 再 Disable voltage（6040h = 0006h、0000h）。</translation>
    </message>
    <message>
        <source>Dry run</source>
        <translation>模擬執行</translation>
    </message>
    <message>
        <source>Show the exact SDO sequence of the enable, without sending anything.</source>
        <translation>顯示致能過程完整的 SDO 順序，不送出任何內容。</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>關閉</translation>
    </message>
    <message>
        <source>Not connected to a bus.</source>
        <translation>未連線到匯流排。</translation>
    </message>
    <message>
        <source>Listen-only connection: the wizard does not send.</source>
        <translation>僅監聽連線：精靈不會傳送。</translation>
    </message>
    <message>
        <source>The bus is not open.</source>
        <translation>匯流排未開啟。</translation>
    </message>
    <message>
        <source>No drive chosen.</source>
        <translation>尚未選擇驅動器。</translation>
    </message>
    <message>
        <source>Node %1 is not being read: press “Read state” to read it again.</source>
        <translation>節點 %1 目前未被讀取：請按「讀取狀態」重新讀取。</translation>
    </message>
    <message>
        <source>Node %1 is not a CiA 402 drive.</source>
        <translation>節點 %1 不是 CiA 402 驅動器。</translation>
    </message>
    <message>
        <source>wizard closed</source>
        <translation>精靈已關閉</translation>
    </message>
    <message>
        <source>Check main power, the enable and safe torque off (STO) inputs, and the drive&apos;s own display.</source>
        <translation>請檢查主電源、致能與安全扭矩關閉（STO）輸入，以及驅動器本身的面板顯示。</translation>
    </message>
    <message>
        <source>Wait for the current step to finish.</source>
        <translation>請等目前步驟完成。</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>運轉致能</translation>
    </message>
    <message>
        <source>Enable operation energises the motor of node %1: it will hold its position and follow commands.

Make sure the machine is safe to move and people are clear.

Send 6040h = 000Fh now?</source>
        <translation>運轉致能會讓節點 %1 的馬達通電：馬達會保持位置並依命令動作。

請確認機台可以安全移動，且人員已離開。

現在送出 6040h = 000Fh？</translation>
    </message>
    <message>
        <source>Enable operation was not confirmed; nothing was sent.</source>
        <translation>未確認運轉致能；沒有送出任何內容。</translation>
    </message>
    <message>
        <source>%1: sending… (%2)</source>
        <translation>%1：傳送中…（%2）</translation>
    </message>
    <message>
        <source>%1 done: the drive is now in %2 (statusword %3h).</source>
        <translation>%1 完成：驅動器目前處於 %2（狀態字 %3h）。</translation>
    </message>
    <message>
        <source>Step “%1” failed: %2.</source>
        <translation>步驟「%1」失敗：%2。</translation>
    </message>
    <message>
        <source>
The drive was sent Disable voltage (6040h = 0000h) and is now in %1.</source>
        <translation>
已對驅動器送出 Disable voltage（6040h = 0000h），目前處於 %1。</translation>
    </message>
    <message>
        <source>
DISABLING FAILED: %1</source>
        <translation>
停用失敗：%1</translation>
    </message>
    <message>
        <source>What to check: </source>
        <translation>檢查事項：</translation>
    </message>
    <message>
        <source>The drive does not list %1 as supported (6502h = %2h).</source>
        <translation>驅動器未列出支援 %1（6502h = %2h）。</translation>
    </message>
    <message>
        <source>Setting the mode of operation: 6060h = %1 (%2), then checking 6061h…</source>
        <translation>設定操作模式：6060h = %1（%2），接著檢查 6061h…</translation>
    </message>
    <message>
        <source>Mode set and verified: the drive shows %1 in 6061h.</source>
        <translation>模式已設定並驗證：驅動器在 6061h 顯示 %1。</translation>
    </message>
    <message>
        <source>Could not set %1: %2</source>
        <translation>無法設定 %1：%2</translation>
    </message>
    <message>
        <source>Enable the drive first (Operation enabled), then arm the test move.</source>
        <translation>請先讓驅動器致能（Operation enabled），再準備測試運轉。</translation>
    </message>
    <message>
        <source>Test move</source>
        <translation>測試運轉</translation>
    </message>
    <message>
        <source>While you hold “Hold to run”, the motor of node %1 will %2, for at most %3 ms.
Releasing the button stops it. Make sure the axis is free to move.

Arm the test move?</source>
        <translation>按住「按住運轉」期間，節點 %1 的馬達將%2，最長 %3 ms。
放開按鈕即停止。請確認軸可以自由移動。

要準備測試運轉嗎？</translation>
    </message>
    <message>
        <source>Test move not armed.</source>
        <translation>未準備測試運轉。</translation>
    </message>
    <message>
        <source>Test move armed: hold the “Hold to run” button to move, release it to stop.</source>
        <translation>測試運轉已就緒：按住「按住運轉」按鈕即移動，放開即停止。</translation>
    </message>
    <message>
        <source>Arm the test move first.</source>
        <translation>請先準備測試運轉。</translation>
    </message>
    <message>
        <source>Test move stopped: %1. The drive stays enabled; press Disable when done.</source>
        <translation>測試運轉已停止：%1。驅動器保持致能；完成後請按「停用」。</translation>
    </message>
    <message>
        <source>Test move failed: %1</source>
        <translation>測試運轉失敗：%1</translation>
    </message>
    <message>
        <source>Moving while the button is held…</source>
        <translation>按住按鈕期間運轉中…</translation>
    </message>
    <message>
        <source>hold-to-run button released</source>
        <translation>已放開「按住運轉」按鈕</translation>
    </message>
    <message>
        <source>Quick stop: %1</source>
        <translation>快速停止：%1</translation>
    </message>
    <message>
        <source>Quick stop: sending 6040h = 0002h…</source>
        <translation>快速停止：送出 6040h = 0002h…</translation>
    </message>
    <message>
        <source>Quick stop done: the drive is in %1.</source>
        <translation>快速停止完成：驅動器處於 %1。</translation>
    </message>
    <message>
        <source>Disable: %1</source>
        <translation>停用：%1</translation>
    </message>
    <message>
        <source>Disabling: Shutdown, then Disable voltage…</source>
        <translation>停用中：先 Shutdown，再 Disable voltage…</translation>
    </message>
    <message>
        <source>The drive is disabled (%1): the motor has no power.</source>
        <translation>驅動器已停用（%1）：馬達無電源。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message numerus="yes">
        <source>Dry run: %n step(s) the enable would send from %1 — nothing was sent. “Save as script…” keeps them for coscope-cli script run.</source>
        <translation>
            <numerusform>模擬執行：致能程序將從 %1 起送出 %n 個步驟——實際上沒有送出任何內容。「另存為腳本…」可保留這些步驟供 coscope-cli script run 使用。</numerusform>
        </translation>
    </message>
    <message>
        <source>Looking for a CiA 402 drive (device type 1000h = …0192h)…</source>
        <translation>尋找 CiA 402 驅動器（裝置類型 1000h = …0192h）…</translation>
    </message>
    <message>
        <source>No CiA 402 drive answered yet; trying again.</source>
        <translation>尚無 CiA 402 驅動器回應；重試中。</translation>
    </message>
    <message>
        <source>another drive was chosen</source>
        <translation>已選擇另一台驅動器</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Node %1 — %2</source>
        <translation>節點 %1 — %2</translation>
    </message>
    <message>
        <source>Reading the identity of node %1 (1018h)…</source>
        <translation>讀取節點 %1 的識別資訊（1018h）…</translation>
    </message>
    <message>
        <source>Node %1 is a %2: %3</source>
        <translation>節點 %1 是 %2：%3</translation>
    </message>
    <message>
        <source>The state of node %1 is not known: not connected.</source>
        <translation>節點 %1 的狀態不明：未連線。</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <source>The drive is initialising (Not ready to switch on); waiting for Switch on disabled…</source>
        <translation>驅動器正在初始化（Not ready to switch on）；等待進入禁止啟動（Switch on disabled）…</translation>
    </message>
    <message>
        <source>The drive finished initialising.</source>
        <translation>驅動器已完成初始化。</translation>
    </message>
    <message>
        <source>Node %1 has no statusword 6041h: it is not a CiA 402 drive (%2).</source>
        <translation>節點 %1 沒有狀態字 6041h：它不是 CiA 402 驅動器（%2）。</translation>
    </message>
    <message>
        <source>Cannot read the drive&apos;s state: %1. Check that the drive is powered and connected, and its node-ID.</source>
        <translation>無法讀取驅動器狀態：%1。請確認驅動器已通電並已連接，以及其節點 ID 是否正確。</translation>
    </message>
    <message>
        <source>Error code 603Fh could not be read: %1</source>
        <translation>無法讀取錯誤碼 603Fh：%1</translation>
    </message>
    <message>
        <source>%1 is %2, not %3: the drive is not in CANopen control and will ignore the controlword. Set %1 = %3 first.</source>
        <translation>%1 為 %2，而非 %3：驅動器不在 CANopen 控制模式，會忽略控制字。請先將 %1 設為 %3。</translation>
    </message>
    <message>
        <source>Mode of operation (6061h): %1</source>
        <translation>操作模式（6061h）：%1</translation>
    </message>
    <message>
        <source>Bus lost. CoScope reconnects by itself; press “Read state” when the bus is back.</source>
        <translation>匯流排中斷。CoScope 會自動重新連線；匯流排恢復後請按「讀取狀態」。</translation>
    </message>
    <message>
        <source>CiA 402 state unknown</source>
        <translation>CiA 402 狀態未知</translation>
    </message>
    <message>
        <source>%1 (statusword %2h)</source>
        <translation>%1（狀態字 %2h）</translation>
    </message>
    <message>
        <source>a state machine step</source>
        <translation>狀態機步驟</translation>
    </message>
    <message>
        <source>the mode of operation is being changed</source>
        <translation>正在變更操作模式</translation>
    </message>
    <message>
        <source>The test move needs %1, which the drive does not list as supported (6502h): no test move in %2.</source>
        <translation>測試運轉需要%1，但驅動器未將其列為支援的模式（6502h）：在%2下不進行測試運轉。</translation>
    </message>
    <message>
        <source>Mode of operation</source>
        <translation>操作模式</translation>
    </message>
    <message>
        <source>The drive is in %1; the test move needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驅動器目前為%1；測試運轉需要%2：要切換操作模式（6060h = %3）嗎？</translation>
    </message>
    <message>
        <source>Test move not armed: the mode of operation stays %1.</source>
        <translation>未準備測試運轉：操作模式維持%1。</translation>
    </message>
    <message>
        <source>Test move armed: holding the “Hold to run” button first switches the mode of operation to %1, then moves; release it to stop.</source>
        <translation>測試運轉已就緒：按住「按住運轉」按鈕時會先將操作模式切換為%1，然後移動；放開即停止。</translation>
    </message>
    <message>
        <source>The test move is no longer armed (%1): arm it again to move.</source>
        <translation>測試運轉已不再就緒（%1）：需再次準備才能移動。</translation>
    </message>
    <message>
        <source>the test move failed</source>
        <translation>測試運轉失敗</translation>
    </message>
    <message>
        <source>the drive faulted</source>
        <translation>驅動器發生故障</translation>
    </message>
    <message>
        <source>the drive left Operation enabled</source>
        <translation>驅動器已離開運轉致能（Operation enabled）</translation>
    </message>
    <message>
        <source>the mode of operation changed</source>
        <translation>操作模式已變更</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>原點復歸</translation>
    </message>
    <message>
        <source>Position move</source>
        <translation>位置移動</translation>
    </message>
    <message>
        <source>The position move is no longer armed (%1): arm it again to move.</source>
        <translation>位置移動已不再就緒（%1）：需再次準備才能移動。</translation>
    </message>
    <message>
        <source>Test move limits: at most %1 per move, at most %2.</source>
        <translation>測試運轉限制：每次最多 %1，速度最高 %2。</translation>
    </message>
    <message>
        <source>Software position limits (607Dh): %1 to %2.</source>
        <translation>軟體限位（607Dh）：%1 至 %2。</translation>
    </message>
    <message>
        <source>No software position limits (607Dh) read.</source>
        <translation>未讀到軟體限位（607Dh）。</translation>
    </message>
    <message>
        <source>Type a homing method number (6098h) or choose one from the list.</source>
        <translation>輸入原點復歸方式編號（6098h）或從清單選擇。</translation>
    </message>
    <message>
        <source>Node %1 (%2) has no homing method %3: its methods are %4. Nothing was sent.</source>
        <translation>節點 %1（%2）沒有原點復歸方式 %3：它的方式為 %4。未發送任何內容。</translation>
    </message>
    <message>
        <source>The drive does not list Homing as supported (6502h): it cannot home.</source>
        <translation>驅動器未列出支援原點復歸（6502h）：無法原點復歸。</translation>
    </message>
    <message>
        <source>The drive is in %1; homing needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驅動器目前為 %1；原點復歸需要 %2：要切換操作模式（6060h = %3）嗎？</translation>
    </message>
    <message>
        <source>Homing not started: the mode of operation stays %1.</source>
        <translation>未開始原點復歸：操作模式維持 %1。</translation>
    </message>
    <message>
        <source>not a CiA 402-2 method</source>
        <translation>不是 CiA 402-2 的方式</translation>
    </message>
    <message>
        <source>The drive is enabled first (Operation enabled): the motor gets power.

</source>
        <translation>會先讓驅動器致能（Operation enabled）：馬達將通電。

</translation>
    </message>
    <message>
        <source>Node %1 will home with method %2: %3.

%4The axis may travel to a limit switch, the home switch or an end stop: make sure it is free to move. Stop halts it at any time.

Start homing?</source>
        <translation>節點 %1 將以方式 %2 進行原點復歸：%3。

%4軸可能移動到極限開關、原點開關或機械極限：請確認它可以自由移動。隨時可按「停止」暫停。

開始原點復歸？</translation>
    </message>
    <message>
        <source>Homing was not confirmed; nothing was sent.</source>
        <translation>未確認原點復歸；未發送任何內容。</translation>
    </message>
    <message>
        <source>homing started</source>
        <translation>已開始原點復歸</translation>
    </message>
    <message>
        <source>Homing node %1 with method %2…</source>
        <translation>節點 %1 以方式 %2 原點復歸中…</translation>
    </message>
    <message>
        <source>Stopping the homing: halt (6040h = 010Fh)…</source>
        <translation>正在停止原點復歸：暫停（6040h = 010Fh）…</translation>
    </message>
    <message>
        <source>Stop pressed</source>
        <translation>已按下「停止」</translation>
    </message>
    <message>
        <source>not read (%1)</source>
        <translation>未讀取（%1）</translation>
    </message>
    <message>
        <source>Homing attained (statusword %1): position actual 6064h = %2. The drive stays enabled.</source>
        <translation>原點復歸完成（狀態字 %1）：實際位置 6064h = %2。驅動器保持致能。</translation>
    </message>
    <message>
        <source>Homing stopped (%1) before home was set.</source>
        <translation>原點復歸在設定原點前已停止（%1）。</translation>
    </message>
    <message>
        <source>Homing failed: %1</source>
        <translation>原點復歸失敗：%1</translation>
    </message>
    <message>
        <source>Enable the drive first (Operation enabled), then arm the position move.</source>
        <translation>請先讓驅動器致能（Operation enabled），再準備位置移動。</translation>
    </message>
    <message>
        <source>Set a profile velocity (6081h) above 0.</source>
        <translation>請設定大於 0 的輪廓速度（6081h）。</translation>
    </message>
    <message>
        <source>The profile velocity is above the test move&apos;s limit of %1.</source>
        <translation>輪廓速度超過測試運轉的限制 %1。</translation>
    </message>
    <message>
        <source>The drive does not list Profile position as supported (6502h): no position move.</source>
        <translation>驅動器未列出支援輪廓位置模式（6502h）：無法位置移動。</translation>
    </message>
    <message>
        <source>Reading the position (6064h) and the software limits (607Dh)…</source>
        <translation>正在讀取位置（6064h）與軟體限位（607Dh）…</translation>
    </message>
    <message>
        <source>Position move not armed: the position 6064h could not be read (%1).</source>
        <translation>位置移動未就緒：無法讀取位置 6064h（%1）。</translation>
    </message>
    <message>
        <source>Position move not armed: the drive is no longer in Operation enabled.</source>
        <translation>位置移動未就緒：驅動器已不在 Operation enabled。</translation>
    </message>
    <message>
        <source>Position move not armed: %1 from the position now is more than the test move&apos;s limit of %2.</source>
        <translation>位置移動未就緒：距目前位置 %1，超過測試運轉的限制 %2。</translation>
    </message>
    <message>
        <source>Position move not armed: it would end at %1, outside the software position limits 607Dh (%2 to %3).</source>
        <translation>位置移動未就緒：會停在 %1，超出軟體限位 607Dh（%2 至 %3）。</translation>
    </message>
    <message>
        <source>The drive is in %1; the position move needs %2: switch the mode of operation (6060h = %3)?</source>
        <translation>驅動器目前為 %1；位置移動需要 %2：要切換操作模式（6060h = %3）嗎？</translation>
    </message>
    <message>
        <source>Position move not armed: the mode of operation stays %1.</source>
        <translation>位置移動未就緒：操作模式維持 %1。</translation>
    </message>
    <message>
        <source>While you hold “Hold to move”, the motor of node %1 will %2.
Releasing the button halts it. Make sure the axis is free to move.

Arm the position move?</source>
        <translation>按住「按住移動」期間，節點 %1 的馬達將%2。
放開按鈕即暫停。請確認軸可以自由移動。

準備位置移動？</translation>
    </message>
    <message>
        <source>Position move not armed.</source>
        <translation>位置移動未就緒。</translation>
    </message>
    <message>
        <source>Position move armed: hold the “Hold to move” button to move, release it to halt.</source>
        <translation>位置移動已就緒：按住「按住移動」按鈕即移動，放開即暫停。</translation>
    </message>
    <message>
        <source>Arm the position move first.</source>
        <translation>請先準備位置移動。</translation>
    </message>
    <message>
        <source>the move was changed after arming</source>
        <translation>準備後移動設定已變更</translation>
    </message>
    <message>
        <source>The position move was changed after it was armed: arm it again.</source>
        <translation>位置移動在準備後已變更：請再次準備。</translation>
    </message>
    <message>
        <source>The move would end outside the software position limits 607Dh: not started.</source>
        <translation>移動會停在軟體限位 607Dh 之外：未開始。</translation>
    </message>
    <message>
        <source>Halted before the target (%1): position actual 6064h = %2, target %3. The drive stays enabled.</source>
        <translation>在到達目標前暫停（%1）：實際位置 6064h = %2，目標 %3。驅動器保持致能。</translation>
    </message>
    <message>
        <source>Target reached (statusword %1): position actual 6064h = %2.</source>
        <translation>已到達目標（狀態字 %1）：實際位置 6064h = %2。</translation>
    </message>
    <message>
        <source>the position move failed</source>
        <translation>位置移動失敗</translation>
    </message>
    <message>
        <source>Position move stopped (%1).</source>
        <translation>位置移動已停止（%1）。</translation>
    </message>
    <message>
        <source>Position move failed: %1</source>
        <translation>位置移動失敗：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ErrorControlDialog</name>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Heartbeat and guarding of node %1</source>
        <translation>節點 %1 的心跳與節點保護</translation>
    </message>
    <message>
        <source>How CoScope watches that node %1 is there (CiA 301 error control). A lost node is raised in the Events.</source>
        <translation>CoScope 如何監看節點 %1 是否在線（CiA 301 錯誤控制）。節點失去時會記入事件。</translation>
    </message>
    <message>
        <source>Not watched</source>
        <translation>不監看</translation>
    </message>
    <message>
        <source>Heartbeat: the node sends it (1017h); lost when none comes within</source>
        <translation>心跳：由節點發送（1017h）；在以下時間內未收到即視為失去</translation>
    </message>
    <message>
        <source>Consumer time:</source>
        <translation>消費者時間：</translation>
    </message>
    <message>
        <source>Node guarding, for a node without heartbeat: CoScope asks (RTR on %1h) every guard time</source>
        <translation>節點保護，用於沒有心跳的節點：CoScope 每個守護時間詢問一次（%1h 上的 RTR）</translation>
    </message>
    <message>
        <source>Guard time (100Ch):</source>
        <translation>守護時間（100Ch）：</translation>
    </message>
    <message>
        <source>Life time factor (100Dh):</source>
        <translation>壽命因子（100Dh）：</translation>
    </message>
    <message>
        <source>Lost after:</source>
        <translation>失去判定：</translation>
    </message>
    <message>
        <source>Node %1 sends a heartbeat. CiA 301 guards only nodes without one (1017h = 0): while it sends both, its heartbeats can be taken for guarding answers.</source>
        <translation>節點 %1 會發送心跳。CiA 301 只對沒有心跳的節點（1017h = 0）做節點保護：兩者同時存在時，其心跳可能被當作保護回應。</translation>
    </message>
    <message>
        <source>%L1 ms without an answer</source>
        <translation>%L1 ms 無回應</translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsDock</name>
    <message>
        <source>Events</source>
        <translation>事件</translation>
    </message>
    <message>
        <source>Double-click an event to show its frame in the trace; click a column&apos;s title to sort</source>
        <translation>按兩下事件可在追蹤中顯示其封包；按欄位標題可排序</translation>
    </message>
    <message>
        <source>Only the events of one node</source>
        <translation>只顯示單一節點的事件</translation>
    </message>
    <message>
        <source>All nodes</source>
        <translation>所有節點</translation>
    </message>
    <message>
        <source>Only the events of one kind</source>
        <translation>只顯示單一類型的事件</translation>
    </message>
    <message>
        <source>All kinds</source>
        <translation>所有類型</translation>
    </message>
    <message>
        <source>Only the events at least this severe</source>
        <translation>只顯示至少達到此嚴重程度的事件</translation>
    </message>
    <message>
        <source>All severities</source>
        <translation>所有嚴重程度</translation>
    </message>
    <message>
        <source>Warnings and errors</source>
        <translation>警告與錯誤</translation>
    </message>
    <message>
        <source>Errors only</source>
        <translation>僅錯誤</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>匯出 CSV…</translation>
    </message>
    <message>
        <source>Write the events shown (with the filters and the order above) to a CSV file</source>
        <translation>將目前顯示的事件（依上方的篩選與排序）寫入 CSV 檔案</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>%L1 of %L2 events</source>
        <translation>%L2 個事件中的 %L1 個</translation>
    </message>
    <message numerus="yes">
        <source>%Ln event(s)</source>
        <translation>
            <numerusform>%Ln 個事件</numerusform>
        </translation>
    </message>
    <message>
        <source>Export events</source>
        <translation>匯出事件</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>The events could not be written: %1</source>
        <translation>無法寫入事件：%1</translation>
    </message>
    <message numerus="yes">
        <source>%Ln event(s) written to %1</source>
        <translation>
            <numerusform>已將 %Ln 個事件寫入 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>coscope::gui::EventsModel</name>
    <message>
        <source>Time (s)</source>
        <translation>時間（秒）</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>事件</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>詳細資料</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>封包</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>嚴重程度</translation>
    </message>
</context>
<context>
    <name>coscope::gui::FrameDetailsView</name>
    <message>
        <source>Field</source>
        <translation>欄位</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Bytes</source>
        <translation>位元組</translation>
    </message>
    <message>
        <source>SDO transfer</source>
        <translation>SDO 傳輸</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>upload (read from the server)</source>
        <translation>上傳（從 SDO 伺服器讀取）</translation>
    </message>
    <message>
        <source>download (write to the server)</source>
        <translation>下載（寫入 SDO 伺服器）</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>模式</translation>
    </message>
    <message>
        <source>block</source>
        <translation>區塊</translation>
    </message>
    <message>
        <source>segmented</source>
        <translation>分段</translation>
    </message>
    <message>
        <source>expedited</source>
        <translation>加速</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>大小</translation>
    </message>
    <message numerus="yes">
        <source>%n byte(s)</source>
        <translation>
            <numerusform>%n 位元組</numerusform>
        </translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>狀態</translation>
    </message>
    <message>
        <source>Abort code</source>
        <translation>中止碼</translation>
    </message>
    <message>
        <source>Abort reason</source>
        <translation>中止原因</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>封包</translation>
    </message>
    <message>
        <source>1 (frame %1)</source>
        <translation>1（封包 %1）</translation>
    </message>
    <message>
        <source>%1 (frames %2–%3)</source>
        <translation>%1（封包 %2–%3）</translation>
    </message>
    <message>
        <source>Duration</source>
        <translation>持續時間</translation>
    </message>
    <message>
        <source>Frame %1</source>
        <translation>封包 %1</translation>
    </message>
    <message>
        <source>Identifier</source>
        <translation>識別碼</translation>
    </message>
    <message>
        <source>Service</source>
        <translation>服務</translation>
    </message>
    <message>
        <source>, node %1</source>
        <translation>，節點 %1</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>長度</translation>
    </message>
    <message>
        <source> (remote request)</source>
        <translation> （遠端請求）</translation>
    </message>
    <message>
        <source>transmitted</source>
        <translation>已傳送</translation>
    </message>
    <message>
        <source>error frame</source>
        <translation>錯誤封包</translation>
    </message>
    <message>
        <source>Flags</source>
        <translation>旗標</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>byte %1</source>
        <translation>位元組 %1</translation>
    </message>
    <message>
        <source>bytes %1–%2</source>
        <translation>位元組 %1–%2</translation>
    </message>
    <message>
        <source>, bit %1</source>
        <translation>，位元 %1</translation>
    </message>
    <message>
        <source>, bits %1–%2</source>
        <translation>，位元 %1–%2</translation>
    </message>
    <message>
        <source>(no payload)</source>
        <translation>（無資料內容）</translation>
    </message>
    <message>
        <source>%1h (%2-bit)</source>
        <translation>%1h（%2 位元）</translation>
    </message>
    <message>
        <source>Loading the frame back from the capture journal…</source>
        <extracomment>Details pane while the selected frame is read back from the capture journal on disk</extracomment>
        <translation>正在從擷取日誌讀回封包…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthDock</name>
    <message>
        <source>Health</source>
        <translation>健康狀態</translation>
    </message>
    <message>
        <source>No frames yet</source>
        <translation>尚無封包</translation>
    </message>
    <message>
        <source>What to look at first, the worst at the top</source>
        <translation>應優先查看的項目，最嚴重的在最上方</translation>
    </message>
    <message>
        <source>Nodes</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>PDOs</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Average load</source>
        <translation>平均負載</translation>
    </message>
    <message>
        <source>Peak load</source>
        <translation>峰值負載</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>時間（秒）</translation>
    </message>
    <message>
        <source>Bus load (%)</source>
        <translation>匯流排負載（%）</translation>
    </message>
    <message>
        <source>Bus load</source>
        <translation>匯流排負載</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) over %1 s; bus load average %2 %, peak %3 % at %4 bit/s; %5 error frame(s)</source>
        <translation>
            <numerusform>%1 秒內共 %n 個封包；匯流排負載平均 %2 %，峰值 %3 %，鮑率 %4 bit/s；%5 個錯誤封包</numerusform>
        </translation>
    </message>
    <message>
        <source>Click a finding to see what happened, why it matters and what to check, and its first frame in the trace.</source>
        <translation>點選發現項目，查看發生了什麼、為何重要、該檢查什麼，並在追蹤中顯示其第一個封包。</translation>
    </message>
    <message>
        <source>Previous occurrence</source>
        <translation>上一次出現</translation>
    </message>
    <message>
        <source>Show the finding&apos;s previous frame in the trace (Shift+F8)</source>
        <translation>在追蹤中顯示此發現項目的上一個封包（Shift+F8）</translation>
    </message>
    <message>
        <source>Next occurrence</source>
        <translation>下一次出現</translation>
    </message>
    <message>
        <source>Show the finding&apos;s next frame in the trace (F8)</source>
        <translation>在追蹤中顯示此發現項目的下一個封包（F8）</translation>
    </message>
    <message>
        <source>%1 critical</source>
        <translation>%1 個嚴重</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 個錯誤</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 個錯誤</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 個警告</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 個警告</translation>
    </message>
    <message>
        <source>No problems found</source>
        <translation>未發現問題</translation>
    </message>
    <message>
        <source>Problems found: %1</source>
        <translation>發現問題：%1</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>Once, at %1.</source>
        <translation>發生一次，於 %1。</translation>
    </message>
    <message>
        <source>%1 times, from %2 to %3.</source>
        <translation>共 %1 次，從 %2 到 %3。</translation>
    </message>
    <message>
        <source>Frame %1 of %2 shown in the trace.</source>
        <translation>追蹤中顯示第 %1 個封包（共 %2 個）。</translation>
    </message>
    <message>
        <source>Click the finding to show its first frame in the trace.</source>
        <translation>點選此發現項目，即可在追蹤中顯示其第一個封包。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Why:&lt;/b&gt;</source>
        <translation>&lt;b&gt;為何重要：&lt;/b&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Check:&lt;/b&gt;</source>
        <translation>&lt;b&gt;檢查：&lt;/b&gt;</translation>
    </message>
    <message>
        <source>CoScope&apos;s own traffic: not counted in the verdict.</source>
        <translation>CoScope 自己的通訊：不計入結論。</translation>
    </message>
    <message>
        <source>Export report…</source>
        <translation>匯出報告…</translation>
    </message>
    <message>
        <source>Save the report for a ticket: an HTML page or a PDF, each finding with the frame numbers it rests on</source>
        <translation>將報告存成可附在工單中的檔案：HTML 網頁或 PDF，每個發現項目都附上其依據的封包編號</translation>
    </message>
    <message>
        <source>HTML page (*.html)</source>
        <translation>HTML 網頁 (*.html)</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export the health report</source>
        <translation>匯出健康報告</translation>
    </message>
    <message>
        <source>The report could not be written: %1</source>
        <translation>無法寫入報告：%1</translation>
    </message>
    <message>
        <source>Health report written to %1</source>
        <translation>健康報告已寫入 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HealthModel</name>
    <message>
        <source>Severity</source>
        <translation>嚴重程度</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>發現項目</translation>
    </message>
    <message>
        <source>State</source>
        <translation>狀態</translation>
    </message>
    <message>
        <source>Error control</source>
        <translation>錯誤控制</translation>
    </message>
    <message>
        <source>Beats</source>
        <translation>心跳次數</translation>
    </message>
    <message>
        <source>Period min/avg/max ms</source>
        <translation>週期 最小/平均/最大 ms</translation>
    </message>
    <message>
        <source>Late</source>
        <translation>延遲</translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation>逾時</translation>
    </message>
    <message>
        <source>Boot-ups</source>
        <translation>上線訊息</translation>
    </message>
    <message>
        <source>Resets</source>
        <translation>重置次數</translation>
    </message>
    <message>
        <source>SDO transfers</source>
        <translation>SDO 傳輸</translation>
    </message>
    <message>
        <source>SDO p99 ms</source>
        <translation>SDO 回應 p99（ms）</translation>
    </message>
    <message>
        <source>SDO aborts</source>
        <translation>SDO 中止</translation>
    </message>
    <message>
        <source>SDO timeouts</source>
        <translation>SDO 逾時</translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation>EMCY</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>封包</translation>
    </message>
    <message>
        <source>Rate Hz</source>
        <translation>頻率 Hz</translation>
    </message>
    <message>
        <source>Jitter ms</source>
        <translation>抖動 ms</translation>
    </message>
    <message>
        <source>Critical</source>
        <translation>嚴重</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>錯誤</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>Info</source>
        <translation>資訊</translation>
    </message>
    <message>
        <source>bus</source>
        <translation>匯流排</translation>
    </message>
    <message>
        <source>none</source>
        <translation>無</translation>
    </message>
    <message>
        <source>guarding stopped</source>
        <translation>節點保護已停止</translation>
    </message>
    <message>
        <source>heartbeat stopped</source>
        <translation>心跳已停止</translation>
    </message>
    <message>
        <source>guarding</source>
        <translation>節點保護</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>%1 (no consumer)</source>
        <translation>%1（無消費者）</translation>
    </message>
    <message>
        <source>event-driven</source>
        <translation>事件驅動</translation>
    </message>
    <message>
        <source>Why:</source>
        <translation>為何重要：</translation>
    </message>
    <message>
        <source>Check:</source>
        <translation>檢查：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::HeartbeatGuardQuestion</name>
    <message>
        <source>Stop the drive if CoScope dies?</source>
        <translation>CoScope 當掉時讓驅動器停止？</translation>
    </message>
    <message>
        <source>Node %1 is enabled by CoScope. Should it stop by itself if CoScope or the cable dies?</source>
        <translation>節點 %1 已由 CoScope 致能。若 CoScope 當掉或線纜斷開，是否讓它自行停止？</translation>
    </message>
    <message>
        <source>CoScope will produce its heartbeat (node %1) every %2 ms and set node %3&apos;s heartbeat consumer 1016h and its abort connection option 6007h (quick stop, where the drive has one), so the drive stops by itself within %4 ms when CoScope or the cable dies. The old values are put back when the drive is disabled or the bus closes.</source>
        <translation>CoScope 將每 %2 ms 發送自己的心跳（節點 %1），並設定節點 %3 的消費者心跳時間 1016h 與中止連線選項 6007h（快速停止，若驅動器有此物件），使 CoScope 當掉或線纜斷開時驅動器在 %4 ms 內自行停止。驅動器禁能或匯流排關閉時會寫回原值。</translation>
    </message>
    <message>
        <source>Guard the drive</source>
        <translation>保護驅動器</translation>
    </message>
    <message>
        <source>Not now</source>
        <translation>暫不</translation>
    </message>
    <message>
        <source>Remember my answer</source>
        <translation>記住我的選擇</translation>
    </message>
    <message>
        <source>Node %1 does not watch CoScope&apos;s heartbeat: if CoScope or the cable dies, it keeps its last command</source>
        <translation>節點 %1 不監看 CoScope 的心跳：若 CoScope 當掉或線纜斷開，它會維持最後的命令</translation>
    </message>
    <message>
        <source>Heartbeat guard: %1</source>
        <translation>心跳保護：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::IntegerSpinBox</name>
    <message>
        <source>Type a number: decimal (31), or hex as 0x1F or 1Fh</source>
        <translation>請輸入數字：十進位 (31)，或十六進位 0x1F 或 1Fh</translation>
    </message>
    <message>
        <source>“%1” is not a number: type it in decimal (31, -5), or in hex as 0x1F or 1Fh</source>
        <translation>「%1」不是數字：請以十進位 (31, -5) 或十六進位 0x1F 或 1Fh 輸入</translation>
    </message>
    <message>
        <source>“%1” is not a number: type it in decimal (31), or in hex as 0x1F or 1Fh</source>
        <translation>「%1」不是數字：請以十進位 (31) 或十六進位 0x1F 或 1Fh 輸入</translation>
    </message>
    <message>
        <source>%1 is out of range: %2 … %3</source>
        <translation>%1 超出範圍：%2 … %3</translation>
    </message>
</context>
<context>
    <name>coscope::gui::JournalOfferBar</name>
    <message>
        <source>Unclosed capture</source>
        <translation>未關閉的擷取</translation>
    </message>
    <message>
        <source>Reopen capture</source>
        <translation>重新開啟擷取</translation>
    </message>
    <message>
        <source>Dismiss</source>
        <translation>忽略</translation>
    </message>
    <message>
        <source>A capture was not closed: CoScope ended without closing it (killed, crashed or the power went out). Its journal %1 (%2, last written %3) holds everything received up to about a second before.</source>
        <translation>有一個擷取未關閉：CoScope 結束時沒有關閉它（被強制終止、當機或斷電）。其日誌 %1（%2，最後寫入於 %3）保存了大約一秒前為止收到的所有內容。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MainWindow</name>
    <message>
        <source>Capture stopped</source>
        <translation>擷取已停止</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>檔案(&amp;F)</translation>
    </message>
    <message>
        <source>&amp;Open log…</source>
        <translation>開啟記錄檔(&amp;O)…</translation>
    </message>
    <message>
        <source>Open CAN log</source>
        <translation>開啟 CAN 記錄檔</translation>
    </message>
    <message>
        <source>&amp;Save trace as…</source>
        <translation>另存追蹤(&amp;S)…</translation>
    </message>
    <message>
        <source>Save trace</source>
        <translation>儲存追蹤</translation>
    </message>
    <message>
        <source>&amp;Export filtered rows…</source>
        <translation>匯出篩選後的資料列(&amp;E)…</translation>
    </message>
    <message>
        <source>Export filtered rows</source>
        <translation>匯出篩選後的資料列</translation>
    </message>
    <message>
        <source>Export PDO layout as &amp;DBC…</source>
        <translation>將 PDO 配置匯出為 &amp;DBC…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>結束(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Bus</source>
        <translation>匯流排(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Connect…</source>
        <translation>連線(&amp;C)…</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>連線</translation>
    </message>
    <message>
        <source>Connect to &amp;virtual drives (sim://)</source>
        <translation>連線到虛擬驅動器（sim://）(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Recent connections</source>
        <translation>最近的連線(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Disconnect</source>
        <translation>中斷連線(&amp;D)</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>匯流排</translation>
    </message>
    <message>
        <source>&amp;Commission</source>
        <translation>調機(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>檢視(&amp;V)</translation>
    </message>
    <message>
        <source>Reset layout</source>
        <translation>重設版面配置</translation>
    </message>
    <message>
        <source>The default layout applies at the next start</source>
        <translation>預設版面配置會在下次啟動時套用</translation>
    </message>
    <message>
        <source>Reopened the capture journal %1</source>
        <translation>已重新開啟擷取日誌 %1</translation>
    </message>
    <message>
        <source>Cannot connect to %1: %2</source>
        <translation>無法連線到 %1：%2</translation>
    </message>
    <message>
        <source>A save is already running</source>
        <translation>已有一個儲存作業在執行</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>請先連線到匯流排</translation>
    </message>
    <message>
        <source>Listen-only bus: commissioning would transmit</source>
        <translation>僅監聽匯流排：調機需要傳送</translation>
    </message>
    <message>
        <source>Listen-only bus</source>
        <translation>僅監聽匯流排</translation>
    </message>
    <message>
        <source>A save is still running; wait for it or cancel it first</source>
        <translation>仍有儲存作業在執行；請等它完成或先取消</translation>
    </message>
    <message>
        <source>Unsaved capture</source>
        <translation>未儲存的擷取</translation>
    </message>
    <message>
        <source>The trace holds %L1 frames that are not saved. Save the capture first?</source>
        <translation>追蹤中有 %L1 個封包尚未儲存。要先儲存擷取內容嗎？</translation>
    </message>
    <message>
        <source>%1: %L2 frames, %L3 lines not understood — first: %4</source>
        <translation>%1：%L2 個封包，%L3 行無法解析——第一行：%4</translation>
    </message>
    <message>
        <source>%1: %L2 frames (%3)</source>
        <translation>%1：%L2 個封包（%3）</translation>
    </message>
    <message>
        <source>Save cancelled</source>
        <translation>已取消儲存</translation>
    </message>
    <message>
        <source>Saved %L1 frames to %2</source>
        <translation>已將 %L1 個封包儲存至 %2</translation>
    </message>
    <message>
        <source>Could not read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 lines, %L4 frames, %L5 lines skipped.</source>
        <translation>%1 以 %2 格式讀取：%L3 行，%L4 個封包，略過 %L5 行。</translation>
    </message>
    <message>
        <source>%1 read as %2: %L3 frames, %L4 records skipped.</source>
        <translation>%1 以 %2 格式讀取：%L3 個封包，略過 %L4 筆記錄。</translation>
    </message>
    <message>
        <source>No frames were found in this file.</source>
        <translation>此檔案中找不到任何封包。</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>… and %L1 more</source>
        <translation>… 另有 %L1 項</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>語言(&amp;L)</translation>
    </message>
    <message>
        <source>System language (%1)</source>
        <extracomment>View ▸ Language: follow the operating system&apos;s language; %1 = that language&apos;s own name</extracomment>
        <translation>系統語言（%1）</translation>
    </message>
    <message>
        <source>Close the other windows (wizards, dialogs) to change the language</source>
        <translation>請先關閉其他視窗（精靈、對話方塊）再切換語言</translation>
    </message>
    <message>
        <source>Capture se&amp;ttings…</source>
        <translation>擷取設定(&amp;T)…</translation>
    </message>
    <message numerus="yes">
        <source>Removed %n old capture journal(s)</source>
        <translation>
            <numerusform>已移除 %n 個舊的擷取日誌</numerusform>
        </translation>
    </message>
    <message>
        <source>An export is already running</source>
        <translation>已有一項匯出正在進行</translation>
    </message>
    <message>
        <source>Recent &amp;logs</source>
        <translation>最近的記錄檔(&amp;L)</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterActions</name>
    <message>
        <source>&amp;SYNC producer</source>
        <translation>SYNC 生產者(&amp;S)</translation>
    </message>
    <message>
        <source>SYNC</source>
        <translation>SYNC</translation>
    </message>
    <message>
        <source>SYNC stopped</source>
        <translation>SYNC 已停止</translation>
    </message>
    <message>
        <source>Cannot start SYNC: %1</source>
        <translation>無法啟動 SYNC：%1</translation>
    </message>
    <message>
        <source>&amp;Master settings…</source>
        <translation>主站設定(&amp;M)…</translation>
    </message>
    <message>
        <source>the bus is listen-only</source>
        <translation>匯流排為僅監聽</translation>
    </message>
    <message>
        <source>no bus is open</source>
        <translation>沒有已開啟的匯流排</translation>
    </message>
    <message>
        <source>SYNC every %1 on %2h</source>
        <translation>SYNC 每 %1 一次，COB-ID %2h</translation>
    </message>
    <message>
        <source>node %1 (%2)</source>
        <translation>節點 %1（%2）</translation>
    </message>
    <message numerus="yes">
        <source>1006h = %1 µs written to %n node(s)</source>
        <translation>
            <numerusform>已將 1006h = %1 µs 寫入 %n 個節點</numerusform>
        </translation>
    </message>
    <message>
        <source>1006h not written to %1</source>
        <translation>1006h 未寫入：%1</translation>
    </message>
    <message>
        <source>Cannot start CoScope&apos;s heartbeat: %1</source>
        <translation>無法啟動 CoScope 的心跳：%1</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>請先連線到匯流排</translation>
    </message>
    <message>
        <source>Listen-only connection: CoScope sends nothing</source>
        <translation>僅監聽連線：CoScope 不發送任何封包</translation>
    </message>
    <message>
        <source>The bus is not open</source>
        <translation>匯流排未開啟</translation>
    </message>
    <message>
        <source>Start or stop the SYNC producer (Bus ▸ Master settings… sets its period)</source>
        <translation>啟動或停止 SYNC 生產者（週期在「匯流排 ▸ 主站設定…」中設定）</translation>
    </message>
    <message>
        <source>SYNC stopped: %1</source>
        <translation>SYNC 已停止：%1</translation>
    </message>
    <message>
        <source>SYNC %1 (%L2)</source>
        <translation>SYNC %1（%L2）</translation>
    </message>
    <message>
        <source>CoScope&apos;s heartbeat keeps running as it is while a drive watches it; the new settings apply once it is released</source>
        <translation>有驅動器監看 CoScope 的心跳時，心跳維持原樣；新設定在釋放後才生效</translation>
    </message>
    <message>
        <source>Heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message numerus="yes">
        <source>guarding node %1</source>
        <translation>
            <numerusform>保護節點 %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterSettings</name>
    <message>
        <source>%1 µs</source>
        <translation>%1 µs</translation>
    </message>
    <message>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
</context>
<context>
    <name>coscope::gui::MasterSettingsDialog</name>
    <message>
        <source>Master settings</source>
        <translation>主站設定</translation>
    </message>
    <message>
        <source>SYNC producer</source>
        <translation>SYNC 生產者</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Communication cycle period (1006h): the time between two SYNC messages, to the microsecond</source>
        <translation>通訊循環週期（1006h）：兩個 SYNC 訊息之間的時間，精確到微秒</translation>
    </message>
    <message>
        <source>Period:</source>
        <translation>週期：</translation>
    </message>
    <message>
        <source>No counter</source>
        <translation>無計數器</translation>
    </message>
    <message>
        <source>Synchronous counter overflow value (1019h): 0 = SYNC without data; 2-240 = SYNC carries a counter 1…N</source>
        <translation>同步計數器溢位值（1019h）：0 = SYNC 不帶資料；2-240 = SYNC 帶計數器 1…N</translation>
    </message>
    <message>
        <source>Counter overflow (1019h):</source>
        <translation>計數器溢位值（1019h）：</translation>
    </message>
    <message>
        <source>COB-ID of the SYNC message (1005h), 80h by default; hex as 80h or 0x80</source>
        <translation>SYNC 訊息的 COB-ID（1005h），預設 80h；十六進位寫成 80h 或 0x80</translation>
    </message>
    <message>
        <source>COB-ID (1005h):</source>
        <translation>COB-ID（1005h）：</translation>
    </message>
    <message>
        <source>Write the period to the nodes&apos; 1006h when SYNC starts</source>
        <translation>SYNC 啟動時將週期寫入各節點的 1006h</translation>
    </message>
    <message>
        <source>CoScope&apos;s heartbeat</source>
        <translation>CoScope 的心跳</translation>
    </message>
    <message>
        <source>CoScope sends a heartbeat (700h + node-ID, state Operational) so that drives whose heartbeat consumer (1016h) watches it stop by themselves when CoScope or the cable goes away</source>
        <translation>CoScope 發送心跳（700h + 節點 ID，狀態為操作狀態），讓以心跳消費者（1016h）監看它的驅動器在 CoScope 或纜線中斷時自行停止</translation>
    </message>
    <message>
        <source>Node-ID:</source>
        <translation>節點 ID：</translation>
    </message>
    <message>
        <source>The counter overflow must be 0 (no counter) or 2-240 (CiA 301, 1019h).</source>
        <translation>計數器溢位值必須為 0（無計數器）或 2-240（CiA 301，1019h）。</translation>
    </message>
    <message>
        <source>The COB-ID “%1” is not a number (write 80h, 0x80 or 128).</source>
        <translation>COB-ID「%1」不是數字（請寫 80h、0x80 或 128）。</translation>
    </message>
    <message>
        <source>The COB-ID %1h is not an 11-bit CAN-ID (set bit 29 for a 29-bit one).</source>
        <translation>COB-ID %1h 不是 11 位元 CAN-ID（29 位元的請設定位元 29）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdChangePage</name>
    <message>
        <source>What to change</source>
        <translation>要變更的項目</translation>
    </message>
    <message>
        <source>The node-ID (the device&apos;s address on the bus, 1-127) or the baud rate (CAN bit rate).</source>
        <translation>節點 ID（裝置在匯流排上的位址，1-127）或鮑率（CAN 位元速率）。</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <source>Baud rate (bit rate)</source>
        <translation>鮑率（位元速率）</translation>
    </message>
    <message>
        <source>LSS (layer setting services, CiA 305) — works for any LSS-capable device</source>
        <translation>LSS（層設定服務，CiA 305）——適用於任何支援 LSS 的裝置</translation>
    </message>
    <message>
        <source>Change:</source>
        <translation>變更：</translation>
    </message>
    <message>
        <source>New node-ID:</source>
        <translation>新節點 ID：</translation>
    </message>
    <message>
        <source>New baud rate:</source>
        <translation>新鮑率：</translation>
    </message>
    <message>
        <source>How:</source>
        <translation>方式：</translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter %1 over SDO — as its manual describes</source>
        <translation>透過 SDO 寫入驅動器自己的參數 %1——依其手冊所述</translation>
    </message>
    <message>
        <source>The drive&apos;s own parameter — none documented for this device</source>
        <translation>驅動器自己的參數——此裝置沒有相關文件</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdFindPage</name>
    <message>
        <source>Find the device</source>
        <translation>找出裝置</translation>
    </message>
    <message>
        <source>Pick the drive whose node-ID or baud rate (bit rate) you want to change.</source>
        <translation>選擇要變更節點 ID 或鮑率（位元速率）的驅動器。</translation>
    </message>
    <message>
        <source>These are the devices CoScope has seen on the bus. &lt;b&gt;Scan&lt;/b&gt; asks every node-ID 1-127 for its device type and identity (SDO reads, changes nothing). A new device without node-ID (LSS-unconfigured) stays silent: &lt;b&gt;Find device without node-ID&lt;/b&gt; finds it with LSS Fastscan (CiA 305).</source>
        <translation>以下是 CoScope 在匯流排上看到的裝置。&lt;b&gt;掃描&lt;/b&gt;會向節點 ID 1-127 逐一查詢裝置類型與識別資訊（SDO 讀取，不變更任何內容）。沒有節點 ID 的新裝置（尚未 LSS 設定）不會發出任何訊息：&lt;b&gt;尋找沒有節點 ID 的裝置&lt;/b&gt;會以 LSS Fastscan（CiA 305）找出它。</translation>
    </message>
    <message>
        <source>Node-ID</source>
        <translation>節點 ID</translation>
    </message>
    <message>
        <source>Device (dictionary)</source>
        <translation>裝置（字典）</translation>
    </message>
    <message>
        <source>State (NMT)</source>
        <translation>狀態（NMT）</translation>
    </message>
    <message>
        <source>Scan the bus</source>
        <translation>掃描匯流排</translation>
    </message>
    <message>
        <source>Find device without node-ID (LSS Fastscan)</source>
        <translation>尋找沒有節點 ID 的裝置（LSS Fastscan）</translation>
    </message>
    <message>
        <source>Scanning node-IDs 1-127…</source>
        <translation>正在掃描節點 ID 1-127…</translation>
    </message>
    <message>
        <source>LSS Fastscan: looking for a device without node-ID…</source>
        <translation>LSS Fastscan：正在尋找沒有節點 ID 的裝置…</translation>
    </message>
    <message numerus="yes">
        <source>Scan finished: %n device(s) known.</source>
        <translation>
            <numerusform>掃描完成：已知 %n 台裝置。</numerusform>
        </translation>
    </message>
    <message>
        <source>(unknown — LSS only)</source>
        <translation>（未知——僅 LSS）</translation>
    </message>
    <message>
        <source>Device type:</source>
        <translation>裝置類型：</translation>
    </message>
    <message>
        <source>(not identified — scan)</source>
        <translation>（未識別——請掃描）</translation>
    </message>
    <message>
        <source>Target: the device without node-ID found by LSS Fastscan.</source>
        <translation>目標：以 LSS Fastscan 找到的無節點 ID 裝置。</translation>
    </message>
    <message>
        <source>Target: node %1%2.</source>
        <translation>目標：節點 %1%2。</translation>
    </message>
    <message>
        <source>No device chosen yet.</source>
        <translation>尚未選擇裝置。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdRunPage</name>
    <message>
        <source>Dry run: nothing has been sent yet. This is exactly what CoScope will send, and why.</source>
        <translation>模擬執行：尚未送出任何內容。以下正是 CoScope 將要送出的內容與原因。</translation>
    </message>
    <message>
        <source>Check and change</source>
        <translation>檢查並變更</translation>
    </message>
    <message>
        <source>Change it now</source>
        <translation>立即變更</translation>
    </message>
    <message>
        <source>Sending: CoScope runs the sequence below; each step turns green when the device has answered.</source>
        <translation>傳送中：CoScope 正在執行下列順序；裝置回應後該步驟會變成綠色。</translation>
    </message>
    <message>
        <source>Takes effect: %1</source>
        <translation>生效時機：%1</translation>
    </message>
    <message>
        <source>CoScope will reconnect at %1 after the first part.</source>
        <translation>第一部分完成後，CoScope 會以 %1 重新連線。</translation>
    </message>
    <message>
        <source>Cannot prepare the change: %1</source>
        <translation>無法準備變更：%1</translation>
    </message>
    <message>
        <source>Sent: the sequence below ran to the end. The device has its new setting.</source>
        <translation>已送出：下列順序已全部執行完畢。裝置已套用新設定。</translation>
    </message>
    <message>
        <source>Stopped: the green steps below were sent, the red one failed, the rest was not sent.</source>
        <translation>已停止：下列綠色步驟已送出，紅色步驟失敗，其餘未送出。</translation>
    </message>
    <message>
        <source>Preparing the sequence…</source>
        <translation>正在準備順序…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodeIdWizard</name>
    <message>
        <source>Baud rate and node-ID — CoScope</source>
        <translation>鮑率與節點 ID — CoScope</translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the devices, so connect first (File ▸ Connect).</source>
        <translation>未連線到匯流排：此精靈需要與裝置通訊，請先連線（檔案 ▸ 連線）。</translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard cannot change anything. Reconnect without listen-only to use it.</source>
        <translation>匯流排以僅監聽方式開啟：CoScope 不會在上面傳送，因此此精靈無法變更任何設定。請取消僅監聽後重新連線再使用。</translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation>匯流排（尚）未開啟：請等待連線完成。</translation>
    </message>
    <message>
        <source>The connection was closed while the change was running. Connect again and scan to see where the device is.</source>
        <translation>變更進行中連線被關閉。請重新連線並掃描，確認裝置目前的位置。</translation>
    </message>
    <message>
        <source>No device without node-ID answered (LSS Fastscan). Every device on the bus has a node-ID.</source>
        <translation>沒有無節點 ID 的裝置回應（LSS Fastscan）。匯流排上每台裝置都有節點 ID。</translation>
    </message>
    <message>
        <source>Found a device without node-ID: vendor %1h, product %2h, serial %3h. It waits in LSS configuration state for its node-ID.</source>
        <translation>找到一台沒有節點 ID 的裝置：廠商 %1h，產品 %2h，序號 %3h。它正在 LSS 設定狀態中等待節點 ID。</translation>
    </message>
    <message>
        <source>Choose a device first.</source>
        <translation>請先選擇裝置。</translation>
    </message>
    <message>
        <source>Choose the new node-ID.</source>
        <translation>請選擇新的節點 ID。</translation>
    </message>
    <message>
        <source>The device already has node-ID %1.</source>
        <translation>裝置的節點 ID 已經是 %1。</translation>
    </message>
    <message>
        <source>Node-ID %1 is already used by another device on this bus: two devices with one node-ID break communication.</source>
        <translation>節點 ID %1 已被此匯流排上的另一台裝置使用：兩台裝置使用同一個節點 ID 會導致通訊中斷。</translation>
    </message>
    <message>
        <source>Choose a bit rate other than the one the bus runs at now (%1).</source>
        <translation>請選擇與匯流排目前鮑率（%1）不同的位元速率。</translation>
    </message>
    <message>
        <source>the device without node-ID</source>
        <translation>無節點 ID 的裝置</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; LSS (layer setting services, CiA 305) picks %1 by its identity (1018h) and gives it the new setting; the device stores it itself.</source>
        <translation>&lt;b&gt;方式：&lt;/b&gt;LSS（層設定服務，CiA 305）依識別資訊（1018h）選中 %1 並給予新設定；裝置會自行儲存。</translation>
    </message>
    <message>
        <source>&lt;b&gt;How:&lt;/b&gt; CoScope writes the drive&apos;s own parameter %1 over SDO (the way its manual describes).</source>
        <translation>&lt;b&gt;方式：&lt;/b&gt;CoScope 透過 SDO 寫入驅動器自己的參數 %1（依其手冊所述的方式）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Takes effect:&lt;/b&gt; %1.</source>
        <translation>&lt;b&gt;生效時機：&lt;/b&gt;%1。</translation>
    </message>
    <message>
        <source>&lt;b&gt;About this drive:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;關於此驅動器：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Every other node on this bus&lt;/b&gt; (%1) stays at %2. After the change, %3 only talks at %4: the others cannot reach it until they are changed too. Change them all, one after another, then the bus runs at %4.</source>
        <translation>&lt;b style=&apos;color:#a40000&apos;&gt;此匯流排上的其他所有節點&lt;/b&gt;（%1）仍維持 %2。變更後，%3 只會以 %4 通訊：其他節點在變更之前都無法與它通訊。請逐一變更所有節點，之後匯流排就會以 %4 運作。</translation>
    </message>
    <message>
        <source>none seen</source>
        <translation>未看到任何節點</translation>
    </message>
    <message>
        <source>nodes %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>CoScope reconnects at the new bit rate by itself and waits for %1 there.</source>
        <translation>CoScope 會自動以新的位元速率重新連線，並在該速率下等待 %1。</translation>
    </message>
    <message>
        <source>&lt;b&gt;If it does not come back:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;如果它沒有重新出現：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>&lt;b style=&apos;color:#a40000&apos;&gt;Cannot do this:&lt;/b&gt; %1</source>
        <translation>&lt;b style=&apos;color:#a40000&apos;&gt;無法執行：&lt;/b&gt;%1</translation>
    </message>
    <message>
        <source>The change is already running.</source>
        <translation>變更已在進行中。</translation>
    </message>
    <message>
        <source>The sequence is not ready yet.</source>
        <translation>順序尚未準備好。</translation>
    </message>
    <message>
        <source>Running…</source>
        <translation>執行中…</translation>
    </message>
    <message>
        <source>The connection is gone: %1</source>
        <translation>連線已中斷：%1</translation>
    </message>
    <message>
        <source>Stopped at %1.
The device answered: %2
What to check: %3</source>
        <translation>停止於 %1。
裝置回應：%2
檢查事項：%3</translation>
    </message>
    <message>
        <source>Done: the device that was %1 now answers at node-ID %2 (it reported on the bus).</source>
        <translation>完成：原本為 %1 的裝置現在以節點 ID %2 回應（已在匯流排上回報）。</translation>
    </message>
    <message>
        <source>without node-ID</source>
        <translation>無節點 ID</translation>
    </message>
    <message>
        <source>Done: node %1 now runs at %2 and CoScope is connected at %2. Nodes still at %3 cannot be reached at this rate: change them too, or reconnect at %3.</source>
        <translation>完成：節點 %1 現在以 %2 運作，CoScope 也已以 %2 連線。仍為 %3 的節點在此速率下無法通訊：請一併變更，或以 %3 重新連線。</translation>
    </message>
    <message>
        <source>The connection is gone before reconnecting.</source>
        <translation>重新連線前連線已中斷。</translation>
    </message>
    <message>
        <source>Reconnecting at %1 (%2)…</source>
        <translation>正在以 %1 重新連線（%2）…</translation>
    </message>
    <message>
        <source>Could not reconnect at %1: %2
%3</source>
        <translation>無法以 %1 重新連線：%2
%3</translation>
    </message>
    <message>
        <source>connected at %1</source>
        <translation>已以 %1 連線</translation>
    </message>
    <message>
        <source>The bus did not open at %1.
%2</source>
        <translation>匯流排無法以 %1 開啟。
%2</translation>
    </message>
    <message>
        <source>Node %1 now answers at node-ID %2 (Baud rate and node-ID wizard)</source>
        <translation>節點 %1 現在以節點 ID %2 回應（鮑率與節點 ID 精靈）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesDock</name>
    <message>
        <source>Nodes</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Scan network (SDO 1000h on nodes 1–127)</source>
        <translation>掃描網路（對節點 1–127 讀取 SDO 1000h）</translation>
    </message>
    <message>
        <source>Scan network</source>
        <translation>掃描網路</translation>
    </message>
    <message>
        <source>Read identity</source>
        <translation>讀取識別資訊</translation>
    </message>
    <message>
        <source>Assign dictionary…</source>
        <translation>指定字典…</translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation>指定字典</translation>
    </message>
    <message>
        <source>Dictionary for node %1:</source>
        <translation>節點 %1 的字典：</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>All nodes</source>
        <translation>所有節點</translation>
    </message>
    <message>
        <source>Listen-only: commands disabled</source>
        <translation>僅監聽：指令已停用</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <source>Scan finished: %1 node(s) answered</source>
        <translation>掃描完成：%1 個節點回應</translation>
    </message>
    <message>
        <source>A scan is running</source>
        <translation>掃描進行中</translation>
    </message>
    <message>
        <source>Listen-only bus: a scan would transmit</source>
        <translation>僅監聽匯流排：掃描需要傳送</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>請先連線到匯流排</translation>
    </message>
    <message>
        <source>Read the device type 1000h of every node-ID 1–127, then each answering node&apos;s identity</source>
        <translation>讀取節點 ID 1–127 每個節點的裝置類型 1000h，再讀取每個有回應節點的識別資訊</translation>
    </message>
    <message>
        <source>Listen-only: NMT commands are disabled</source>
        <translation>僅監聽：NMT 指令已停用</translation>
    </message>
    <message>
        <source>Not connected to a bus</source>
        <translation>未連線到匯流排</translation>
    </message>
    <message>
        <source>An NMT command is waiting for your answer</source>
        <translation>有一個 NMT 指令正在等待您的回覆</translation>
    </message>
    <message>
        <source>all nodes</source>
        <translation>所有節點</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Send NMT “%1” to %2?

Frame: %3</source>
        <translation>要將 NMT「%1」送給 %2 嗎？

封包：%3</translation>
    </message>
    <message>
        <source>Send NMT command</source>
        <translation>送出 NMT 指令</translation>
    </message>
    <message>
        <source>NMT %1 to %2 failed: %3</source>
        <translation>對 %2 送出 NMT %1 失敗：%3</translation>
    </message>
    <message>
        <source>NMT command failed</source>
        <translation>NMT 指令失敗</translation>
    </message>
    <message>
        <source>Sent NMT %1 to %2</source>
        <translation>已對 %2 送出 NMT %1</translation>
    </message>
    <message>
        <source>Drive %1 is enabled (Operation enabled, statusword 0x%2): %3 stops it abruptly; the motor loses torque or trips its communication-loss reaction (6007h). %4Disable it first (CiA 402 wizard: Disable).

</source>
        <translation>驅動器 %1 已致能（Operation enabled，狀態字 0x%2）：%3會讓它突然停止；馬達會失去扭矩或觸發通訊中斷處理（6007h）。%4請先停用（CiA 402 精靈：停用）。

</translation>
    </message>
    <message>
        <source>a reset</source>
        <translation>重置</translation>
    </message>
    <message>
        <source>this command</source>
        <translation>此指令</translation>
    </message>
    <message>
        <source>Delta drives raise AL401 (CANopen communication lost). </source>
        <translation>台達驅動器會發出 AL401（CANopen 通訊中斷）。</translation>
    </message>
    <message>
        <source>Scan needs a connected bus that is not listen-only</source>
        <translation>掃描需要已連線且非僅監聽的匯流排</translation>
    </message>
    <message>
        <source>A scan is already running</source>
        <translation>已有掃描在進行中</translation>
    </message>
    <message>
        <source>Read object 1000h from every node-ID 1–127 (SDO upload requests on 601h–67Fh)?</source>
        <translation>要從節點 ID 1–127 逐一讀取物件 1000h 嗎（在 601h–67Fh 送出 SDO 上傳請求）？</translation>
    </message>
    <message>
        <source>Scanning nodes 1–127…</source>
        <translation>正在掃描節點 1–127…</translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation>節點 %1 使用字典 %2</translation>
    </message>
    <message>
        <source>Heartbeat and guarding…</source>
        <translation>心跳與節點保護…</translation>
    </message>
    <message>
        <source>Listen-only bus: node guarding would transmit (an RTR each guard time); a heartbeat can still be watched.</source>
        <translation>僅監聽匯流排：節點保護需要發送（每個守護時間一個 RTR）；仍可監看心跳。</translation>
    </message>
    <message>
        <source>The bus is not open: node guarding cannot send its requests.</source>
        <translation>匯流排未開啟：節點保護無法發送請求。</translation>
    </message>
    <message>
        <source>Node guarding of node %1 not started: %2</source>
        <translation>節點 %1 的節點保護未啟動：%2</translation>
    </message>
    <message>
        <source>Node guarding</source>
        <translation>節點保護</translation>
    </message>
    <message>
        <source>Node %1: node guarding every %2 ms, lost after %3 ms without an answer</source>
        <translation>節點 %1：每 %2 ms 節點保護一次，%3 ms 無回應即視為失去</translation>
    </message>
    <message>
        <source>Node %1: heartbeat expected within %2 ms</source>
        <translation>節點 %1：預期 %2 ms 內收到心跳</translation>
    </message>
    <message>
        <source>Node %1 is no longer watched</source>
        <translation>節點 %1 不再監看</translation>
    </message>
    <message>
        <source>Download program…</source>
        <translation>下載程式…</translation>
    </message>
    <message>
        <source>Listen-only bus: a program download would transmit</source>
        <translation>僅監聽匯流排：程式下載需要發送訊息</translation>
    </message>
    <message>
        <source>Select a node first</source>
        <translation>請先選擇節點</translation>
    </message>
    <message>
        <source>Load a new program (firmware) into the node: CiA 302-3 program download</source>
        <translation>將新程式（韌體）載入節點：CiA 302-3 程式下載</translation>
    </message>
</context>
<context>
    <name>coscope::gui::NodesModel</name>
    <message>
        <source>No heartbeat</source>
        <translation>無心跳</translation>
    </message>
    <message>
        <source>Unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>not present</source>
        <translation>不存在</translation>
    </message>
    <message>
        <source>Device name (1008h): %1
Hardware version (1009h): %2
Software version (100Ah): %3</source>
        <translation>裝置名稱（1008h）：%1
硬體版本（1009h）：%2
軟體版本（100Ah）：%3</translation>
    </message>
    <message>
        <source>vendor %1</source>
        <translation>廠商 %1</translation>
    </message>
    <message>
        <source>, product %1</source>
        <translation>，產品 %1</translation>
    </message>
    <message>
        <source>, product not present</source>
        <translation>，無產品資訊</translation>
    </message>
    <message>
        <source>, rev %1</source>
        <translation>，版次 %1</translation>
    </message>
    <message>
        <source>, rev not present</source>
        <translation>，無版次資訊</translation>
    </message>
    <message>
        <source>, s/n %1</source>
        <translation>，序號 %1</translation>
    </message>
    <message>
        <source>, s/n not present</source>
        <translation>，無序號資訊</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（無）</translation>
    </message>
    <message>
        <source>boot-up</source>
        <translation>上線訊息</translation>
    </message>
    <message>
        <source>heartbeat</source>
        <translation>心跳</translation>
    </message>
    <message>
        <source>scan</source>
        <translation>掃描</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>NMT state</source>
        <translation>NMT 狀態</translation>
    </message>
    <message>
        <source>Heartbeat age</source>
        <translation>心跳經過時間</translation>
    </message>
    <message>
        <source>Device name</source>
        <translation>裝置名稱</translation>
    </message>
    <message>
        <source>Identity (1018h)</source>
        <translation>識別資訊（1018h）</translation>
    </message>
    <message>
        <source>Dictionary</source>
        <translation>字典</translation>
    </message>
    <message>
        <source>EMCY</source>
        <translation>EMCY</translation>
    </message>
    <message>
        <source>Seen by</source>
        <translation>偵測來源</translation>
    </message>
    <message>
        <source>unknown (gap)</source>
        <translation>未知（中斷）</translation>
    </message>
    <message>
        <source>node guarding</source>
        <translation>節點保護</translation>
    </message>
    <message>
        <source>after our NMT %1 (not confirmed)</source>
        <translation>在我們送出 NMT %1 之後（未確認）</translation>
    </message>
    <message>
        <source>after NMT %1 by another master (not confirmed)</source>
        <translation>在另一個主站送出 NMT %1 之後（未確認）</translation>
    </message>
    <message>
        <source>its PDOs</source>
        <translation>其 PDO</translation>
    </message>
    <message>
        <source>its SDO answers</source>
        <translation>其 SDO 回應</translation>
    </message>
    <message>
        <source>its EMCY</source>
        <translation>其緊急訊息 (EMCY)</translation>
    </message>
    <message>
        <source>The node sent its boot-up message; after boot-up a node is Pre-operational.</source>
        <translation>節點送出了上線訊息；上線後節點處於預操作狀態。</translation>
    </message>
    <message>
        <source>The node&apos;s heartbeat says so.</source>
        <translation>由節點的心跳得知。</translation>
    </message>
    <message>
        <source>The node&apos;s answer to node guarding says so.</source>
        <translation>由節點對節點保護的回應得知。</translation>
    </message>
    <message>
        <source>CoScope sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its own that shows its state).</source>
        <translation>CoScope 送出了 NMT %1；節點尚未確認（沒有心跳，也沒有能顯示其狀態的自身封包）。</translation>
    </message>
    <message>
        <source>Another master sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its own that shows its state).</source>
        <translation>另一個主站送出了 NMT %1；節點尚未確認（沒有心跳，也沒有能顯示其狀態的自身封包）。</translation>
    </message>
    <message>
        <source>The node sends PDOs, which CiA 301 allows only in Operational.</source>
        <translation>節點正在送出 PDO，而 CiA 301 只允許在操作狀態下送出。</translation>
    </message>
    <message>
        <source>The node answers SDO, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show Operational).</source>
        <translation>節點回應 SDO，而 CiA 301 只允許在預操作狀態與操作狀態下回應（其 PDO 才能顯示是否為操作狀態）。</translation>
    </message>
    <message>
        <source>The node sends EMCY, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show Operational).</source>
        <translation>節點送出緊急訊息 (EMCY)，而 CiA 301 只允許在預操作狀態與操作狀態下送出（其 PDO 才能顯示是否為操作狀態）。</translation>
    </message>
    <message>
        <source>Nothing seen yet shows the node&apos;s state.</source>
        <translation>目前所見的內容尚無法顯示節點的狀態。</translation>
    </message>
    <message>
        <source>The bus was lost: the state is unknown until the node&apos;s heartbeat or its own frames show it (last known: %1)</source>
        <translation>匯流排中斷：在節點的心跳或其自身封包顯示狀態之前，狀態未知（最後已知：%1）</translation>
    </message>
    <message>
        <source>State from</source>
        <translation>狀態來源</translation>
    </message>
    <message>
        <source>guarding %1 ms × %2</source>
        <translation>節點保護 %1 ms × %2</translation>
    </message>
    <message>
        <source>heartbeat %1 ms</source>
        <translation>心跳 %1 ms</translation>
    </message>
    <message>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>正常</translation>
    </message>
    <message>
        <source>late</source>
        <translation>延遲</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>失去</translation>
    </message>
    <message>
        <source>%1, %2 s ago</source>
        <translation>%1，%2 秒前</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Not watched by CoScope (Heartbeat and guarding… in the context menu)</source>
        <translation>CoScope 未監看（右鍵選單中的「心跳與節點保護…」）</translation>
    </message>
    <message>
        <source>Node guarding (CiA 301): CoScope asks every %1 ms; the node is late when a request goes unanswered or the toggle bit is wrong, lost after %2 ms without a right answer. Guarding errors: %3, lost %4 time(s).</source>
        <translation>節點保護（CiA 301）：CoScope 每 %1 ms 詢問一次；請求無回應或切換位元錯誤時視為延遲，%2 ms 內無正確回應即視為失去。保護錯誤：%3，失去 %4 次。</translation>
    </message>
    <message>
        <source>Heartbeat consumer (CiA 301): late when a heartbeat is overdue, lost when none comes within %1 ms. Lost %2 time(s).</source>
        <translation>心跳消費者（CiA 301）：心跳逾時視為延遲，%1 ms 內未收到即視為失去。失去 %2 次。</translation>
    </message>
    <message>
        <source>Heartbeat / guarding</source>
        <translation>心跳 / 節點保護</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ObjectDictionaryDock</name>
    <message>
        <source>Object Dictionary</source>
        <translation>物件字典</translation>
    </message>
    <message>
        <source>Search index or name (6060, 0x1018, heartbeat)</source>
        <translation>搜尋索引或名稱（6060、0x1018、heartbeat）</translation>
    </message>
    <message>
        <source>Only changed</source>
        <translation>僅顯示已變更</translation>
    </message>
    <message>
        <source>Show only the values read from the node that differ from the dictionary&apos;s default</source>
        <translation>只顯示從節點讀取、且與字典預設值不同的值</translation>
    </message>
    <message>
        <source>Read all</source>
        <translation>全部讀取</translation>
    </message>
    <message>
        <source>Read every readable object of the node over SDO (DOMAINs are skipped)</source>
        <translation>透過 SDO 讀取節點所有可讀的物件（略過 DOMAIN）</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Export DCF…</source>
        <translation>匯出 DCF…</translation>
    </message>
    <message>
        <source>Export node %1 as DCF</source>
        <translation>將節點 %1 匯出為 DCF</translation>
    </message>
    <message>
        <source>Device configuration (*.dcf)</source>
        <translation>裝置組態（*.dcf）</translation>
    </message>
    <message>
        <source>Apply DCF…</source>
        <translation>套用 DCF…</translation>
    </message>
    <message>
        <source>Apply a DCF to node %1</source>
        <translation>將 DCF 套用到節點 %1</translation>
    </message>
    <message>
        <source>Device configuration (*.dcf *.eds);;All files (*)</source>
        <translation>裝置組態（*.dcf *.eds）;;所有檔案（*）</translation>
    </message>
    <message>
        <source>Assign dictionary</source>
        <translation>指定字典</translation>
    </message>
    <message>
        <source>Read</source>
        <translation>讀取</translation>
    </message>
    <message>
        <source>Write value…</source>
        <translation>寫入值…</translation>
    </message>
    <message>
        <source>Copy value</source>
        <translation>複製值</translation>
    </message>
    <message>
        <source>Copy error</source>
        <translation>複製錯誤</translation>
    </message>
    <message>
        <source>Expand all</source>
        <translation>全部展開</translation>
    </message>
    <message>
        <source>Collapse all</source>
        <translation>全部收合</translation>
    </message>
    <message>
        <source>Listen-only: SDO disabled</source>
        <translation>僅監聽：SDO 已停用</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未連線</translation>
    </message>
    <message>
        <source>Reading node %1 stopped: another node was chosen</source>
        <translation>已停止讀取節點 %1：已選擇另一個節點</translation>
    </message>
    <message>
        <source>Dictionary %1 of node %2 cannot be loaded</source>
        <translation>無法載入節點 %2 的字典 %1</translation>
    </message>
    <message>
        <source>Node %1 uses dictionary %2</source>
        <translation>節點 %1 使用字典 %2</translation>
    </message>
    <message>
        <source>&lt;b&gt;No node selected&lt;/b&gt; — pick one in the Nodes dock</source>
        <translation>&lt;b&gt;未選擇節點&lt;/b&gt;——請在「節點」面板中選擇一個</translation>
    </message>
    <message>
        <source>Select a node in the Nodes dock to see its object dictionary.</source>
        <translation>在「節點」面板中選擇一個節點，即可查看其物件字典。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Node %1&lt;/b&gt;</source>
        <translation>&lt;b&gt;節點 %1&lt;/b&gt;</translation>
    </message>
    <message>
        <source> · &lt;span style=&apos;color:#b00020&apos;&gt;no dictionary&lt;/span&gt;</source>
        <translation> · &lt;span style=&apos;color:#b00020&apos;&gt;無字典&lt;/span&gt;</translation>
    </message>
    <message>
        <source> · %1 entries, %2 read</source>
        <translation> · %1 個項目，已讀取 %2 個</translation>
    </message>
    <message>
        <source> · &lt;i&gt;listen-only: no SDO&lt;/i&gt;</source>
        <translation> · &lt;i&gt;僅監聽：無 SDO&lt;/i&gt;</translation>
    </message>
    <message>
        <source> · &lt;i&gt;offline: no SDO&lt;/i&gt;</source>
        <translation> · &lt;i&gt;離線：無 SDO&lt;/i&gt;</translation>
    </message>
    <message>
        <source>No dictionary is known for node %1: it was not identified (1018h) or matched none in the library. Assign one to see its objects.</source>
        <translation>節點 %1 沒有已知的字典：它尚未識別（1018h），或與字典庫中的任何一個都不相符。請指定字典以查看其物件。</translation>
    </message>
    <message>
        <source>%1: no node selected</source>
        <translation>%1：未選擇節點</translation>
    </message>
    <message>
        <source>%1: no dictionary for node %2 (assign one)</source>
        <translation>%1：節點 %2 沒有字典（請指定一個）</translation>
    </message>
    <message>
        <source>%1: the bus is listen-only, nothing is sent</source>
        <translation>%1：匯流排為僅監聽，不會傳送任何內容</translation>
    </message>
    <message>
        <source>%1: not connected to a bus</source>
        <translation>%1：未連線到匯流排</translation>
    </message>
    <message>
        <source>Read %1</source>
        <translation>讀取 %1</translation>
    </message>
    <message>
        <source>%1 %2 is write-only</source>
        <translation>%1 %2 為唯寫</translation>
    </message>
    <message>
        <source>Node %1 %2 %3 = %4</source>
        <translation>節點 %1 %2 %3 = %4</translation>
    </message>
    <message>
        <source>Write %1 %2 = %3 to node %4?</source>
        <translation>要將 %1 %2 = %3 寫入節點 %4 嗎？</translation>
    </message>
    <message>
        <source>Node %1 %2: %3</source>
        <translation>節點 %1 %2：%3</translation>
    </message>
    <message>
        <source>Write %1</source>
        <translation>寫入 %1</translation>
    </message>
    <message>
        <source>%1 %2 is %3: not writable</source>
        <translation>%1 %2 為 %3：不可寫入</translation>
    </message>
    <message>
        <source>Write object</source>
        <translation>寫入物件</translation>
    </message>
    <message numerus="yes">
        <source>

SDO download of %n byte(s): %1</source>
        <translation>
            <numerusform>

SDO 下載 %n 位元組：%1</numerusform>
        </translation>
    </message>
    <message>
        <source>Node %1 %2 written: %3</source>
        <translation>節點 %1 %2 已寫入：%3</translation>
    </message>
    <message>
        <source>A read or DCF application is already running</source>
        <translation>已有讀取或 DCF 套用作業在執行</translation>
    </message>
    <message>
        <source>Reading %1 objects of node %2…</source>
        <translation>正在讀取節點 %2 的 %1 個物件…</translation>
    </message>
    <message>
        <source>Read of node %1 cancelled: %2 values read</source>
        <translation>已取消讀取節點 %1：已讀取 %2 個值</translation>
    </message>
    <message>
        <source>Node %1: %2 values read, %3 refused (red rows; the tool tip has the abort text)</source>
        <translation>節點 %1：已讀取 %2 個值，%3 個被拒絕（紅色資料列；工具提示中有中止說明）</translation>
    </message>
    <message>
        <source>Node %1: %2 values read</source>
        <translation>節點 %1：已讀取 %2 個值</translation>
    </message>
    <message>
        <source>Export of node %1 failed: %2</source>
        <translation>匯出節點 %1 失敗：%2</translation>
    </message>
    <message>
        <source>Node %1: %2 values exported to %3</source>
        <translation>節點 %1：已將 %2 個值匯出至 %3</translation>
    </message>
    <message>
        <source>Export: no node with a dictionary selected</source>
        <translation>匯出：未選擇有字典的節點</translation>
    </message>
    <message>
        <source>Export: wait for the running read to finish</source>
        <translation>匯出：請等待目前的讀取完成</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <source>Apply DCF</source>
        <translation>套用 DCF</translation>
    </message>
    <message>
        <source>Apply DCF: wait for the running read to finish</source>
        <translation>套用 DCF：請等待目前的讀取完成</translation>
    </message>
    <message>
        <source>%1 is not a usable DCF: %2</source>
        <translation>%1 不是可用的 DCF：%2</translation>
    </message>
    <message>
        <source>no object could be read</source>
        <translation>沒有任何物件可以讀取</translation>
    </message>
    <message>
        <source>Reading node %1&apos;s current values of the %2 candidates in %3…</source>
        <translation>正在讀取節點 %1 在 %3 中 %2 個候選項目的目前值…</translation>
    </message>
    <message>
        <source>Apply DCF cancelled</source>
        <translation>已取消套用 DCF</translation>
    </message>
    <message>
        <source>Node %1 already has every value of %2 (%3 entries not written)</source>
        <translation>節點 %1 已具有 %2 的所有值（%3 個項目未寫入）</translation>
    </message>
    <message>
        <source>Apply DCF: the bus can no longer transmit</source>
        <translation>套用 DCF：匯流排已無法傳送</translation>
    </message>
    <message>
        <source>Writing %1 objects to node %2…</source>
        <translation>正在將 %1 個物件寫入節點 %2…</translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 written, %3 refused — first: %4</source>
        <translation>已將 DCF 套用到節點 %1：寫入 %2 個，%3 個被拒絕——第一個：%4</translation>
    </message>
    <message>
        <source>DCF applied to node %1: %2 objects written%3</source>
        <translation>已將 DCF 套用到節點 %1：寫入 %2 個物件%3</translation>
    </message>
    <message>
        <source> (cancelled)</source>
        <translation> （已取消）</translation>
    </message>
    <message>
        <source>Node %1: not written: %2</source>
        <translation>節點 %1：未寫入：%2</translation>
    </message>
    <message>
        <source>Node %1 now answers at node-ID %2: showing node %2. Values read at node %1 were dropped; read them again.</source>
        <translation>節點 %1 現在以節點 ID %2 回應：顯示節點 %2。在節點 %1 讀取的值已捨棄；請重新讀取。</translation>
    </message>
    <message>
        <source>Concise DCF, CiA 302-3 (*.bin)</source>
        <translation>精簡 DCF，CiA 302-3 (*.bin)</translation>
    </message>
    <message>
        <source>Node %1: concise DCF with %2 entries (%3 bytes) exported to %4</source>
        <translation>節點 %1：含 %2 個項目（%3 位元組）的精簡 DCF 已匯出至 %4</translation>
    </message>
</context>
<context>
    <name>coscope::gui::OdTreeModel</name>
    <message>
        <source>Index</source>
        <translation>索引</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>類型</translation>
    </message>
    <message>
        <source>Access</source>
        <translation>存取</translation>
    </message>
    <message>
        <source>PDO</source>
        <translation>PDO</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>預設值</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoApplyPage</name>
    <message>
        <source>Check and apply</source>
        <translation>檢查並套用</translation>
    </message>
    <message>
        <source>This is exactly what will be sent, step by step (dry run: nothing has been sent yet). If the drive refuses a step, the wizard stops, tells you why and writes the old settings back.</source>
        <translation>以下正是將逐步送出的內容（模擬執行：尚未送出任何內容）。若驅動器拒絕某個步驟，精靈會停止、說明原因，並寫回原本的設定。</translation>
    </message>
    <message>
        <source>Keep after power-off: store the drive&apos;s parameters (1010h:01 = &quot;save&quot;)</source>
        <translation>斷電後保留：儲存驅動器參數（1010h:01 = &quot;save&quot;）</translation>
    </message>
    <message>
        <source>Start the drive&apos;s process data afterwards (NMT start: operational)</source>
        <translation>完成後啟動驅動器的過程資料（NMT 啟動：操作狀態）</translation>
    </message>
    <message>
        <source>Apply to the drive</source>
        <translation>套用到驅動器</translation>
    </message>
    <message>
        <source>Without this the new mapping is lost when the drive is switched off or reset</source>
        <translation>若不勾選，驅動器斷電或重置後新的映射就會遺失</translation>
    </message>
    <message>
        <source>This drive&apos;s dictionary has no 1010h (store parameters)</source>
        <translation>此驅動器的字典沒有 1010h（儲存參數）</translation>
    </message>
    <message>
        <source>Applying…</source>
        <translation>套用中…</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoChoosePage</name>
    <message>
        <source>Which drive and which message</source>
        <translation>哪台驅動器、哪個訊息</translation>
    </message>
    <message>
        <source>A PDO (process data object) is one CAN message that carries up to 8 bytes of live values. The drive sends its TPDOs (transmit PDOs, e.g. status and position) and receives its RPDOs (receive PDOs, e.g. commands).</source>
        <translation>PDO（過程資料物件）是一個 CAN 訊息，最多攜帶 8 位元組的即時數值。驅動器會傳送它的 TPDO（傳送 PDO，例如狀態與位置），並接收它的 RPDO（接收 PDO，例如命令）。</translation>
    </message>
    <message>
        <source>%1 — the drive sends (transmit PDO %2)</source>
        <translation>%1——驅動器傳送（傳送 PDO %2）</translation>
    </message>
    <message>
        <source>%1 — the drive receives (receive PDO %2)</source>
        <translation>%1——驅動器接收（接收 PDO %2）</translation>
    </message>
    <message>
        <source>Byte</source>
        <translation>位元組</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>Bits</source>
        <translation>位元</translation>
    </message>
    <message>
        <source>Drive (node):</source>
        <translation>驅動器（節點）：</translation>
    </message>
    <message>
        <source>Message (PDO):</source>
        <translation>訊息（PDO）：</translation>
    </message>
    <message>
        <source>Node %1 (no dictionary)</source>
        <translation>節點 %1（無字典）</translation>
    </message>
    <message>
        <source>Node %1 — %2%3</source>
        <translation>節點 %1 — %2%3</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Waiting for a drive to appear on the bus…</source>
        <translation>正在等待驅動器出現在匯流排上…</translation>
    </message>
    <message>
        <source>Reading %1 of node %2 from the drive (SDO upload of %3h and %4h)…</source>
        <translation>正在從驅動器讀取節點 %2 的 %1（SDO 上傳 %3h 與 %4h）…</translation>
    </message>
    <message>
        <source>Could not read %1 of node %2: %3</source>
        <translation>無法讀取節點 %2 的 %1：%3</translation>
    </message>
    <message>
        <source>CAN-ID %1h%2. %3. %4 of 64 bits used.</source>
        <translation>CAN-ID %1h%2。%3。已使用 64 位元中的 %4 位元。</translation>
    </message>
    <message>
        <source> (switched off: COB-ID bit 31 set)</source>
        <translation> （已關閉：COB-ID 位元 31 已設定）</translation>
    </message>
    <message>
        <source>Dry run (the bus is listen-only, nothing is sent): starting from the dictionary&apos;s defaults, not read from the drive: %1</source>
        <translation>模擬執行（匯流排為僅監聽，不會傳送任何內容）：以字典預設值為起點，而非從驅動器讀取：%1</translation>
    </message>
    <message>
        <source>Now in the drive: %1</source>
        <translation>驅動器目前：%1</translation>
    </message>
    <message>
        <source>(nothing mapped: the message is empty)</source>
        <translation>（沒有映射：訊息為空）</translation>
    </message>
    <message>
        <source>Good to know about this drive:</source>
        <translation>關於此驅動器的注意事項：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoFrameLayout</name>
    <message>
        <source>byte %1</source>
        <translation>位元組 %1</translation>
    </message>
    <message>
        <source>%1 of 64 bits — too long: a PDO carries at most 8 bytes</source>
        <translation>64 位元中的 %1 位元——太長：一個 PDO 最多攜帶 8 位元組</translation>
    </message>
    <message>
        <source>%1 of 64 bits used (%2 bytes in the frame)</source>
        <translation>已使用 64 位元中的 %1 位元（封包中 %2 位元組）</translation>
    </message>
    <message>
        <source>byte %1: %3</source>
        <extracomment>PDO layout tooltip: the bytes of the frame a mapped object fills, then its name (%3)</extracomment>
        <translation>位元組 %1：%3</translation>
    </message>
    <message>
        <source>byte %1-%2: %3</source>
        <translation>位元組 %1–%2：%3</translation>
    </message>
    <message>
        <source>%1 of 64 bits</source>
        <translation>已用 %1 / 64 位元</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoMappingPage</name>
    <message>
        <source>What the message carries</source>
        <translation>訊息攜帶的內容</translation>
    </message>
    <message>
        <source>Pick the values to put in the message, in the order they appear in the frame (the PDO mapping). Double-click or drag an object to the right; drag or use Up/Down to reorder. A frame holds at most 8 bytes (64 bits).</source>
        <translation>依封包中出現的順序挑選要放進訊息的值（即 PDO 映射）。按兩下物件或將其拖曳到右側；以拖曳或「上移／下移」調整順序。一個封包最多 8 位元組（64 位元）。</translation>
    </message>
    <message>
        <source>Search by name or index, e.g. velocity or 606C</source>
        <translation>依名稱或索引搜尋，例如 velocity 或 606C</translation>
    </message>
    <message>
        <source>Add →</source>
        <translation>加入 →</translation>
    </message>
    <message>
        <source>← Remove</source>
        <translation>← 移除</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>上移</translation>
    </message>
    <message>
        <source>Down</source>
        <translation>下移</translation>
    </message>
    <message>
        <source>Clear</source>
        <translation>清除</translation>
    </message>
    <message>
        <source>As in the drive</source>
        <translation>與驅動器相同</translation>
    </message>
    <message>
        <source>Start again from the mapping read from the drive</source>
        <translation>從驅動器讀到的映射重新開始</translation>
    </message>
    <message>
        <source>Objects this drive allows in the message:</source>
        <translation>此驅動器允許放入訊息的物件：</translation>
    </message>
    <message>
        <source>In the message, in frame order:</source>
        <translation>訊息內容（依封包順序）：</translation>
    </message>
    <message>
        <source>The frame, byte by byte:</source>
        <translation>封包逐位元組內容：</translation>
    </message>
    <message>
        <source>(no dictionary for this node: objects cannot be listed)</source>
        <translation>（此節點沒有字典：無法列出物件）</translation>
    </message>
    <message>
        <source>%1  (%2, %3 bits)</source>
        <translation>%1  （%2，%3 位元）</translation>
    </message>
    <message>
        <source>%1h:%2 — %3, access %4</source>
        <translation>%1h:%2 — %3，存取 %4</translation>
    </message>
    <message>
        <source>Cannot add: %1</source>
        <translation>無法加入：%1</translation>
    </message>
    <message>
        <source>%1  (%2 bits)</source>
        <translation>%1  （%2 位元）</translation>
    </message>
    <message>
        <source>Too long: %1 bits. Remove objects until the total is 64 bits or less.</source>
        <translation>太長：%1 位元。請移除物件直到總長度不超過 64 位元。</translation>
    </message>
    <message>
        <source>Nothing mapped: the message would carry no data.</source>
        <translation>沒有映射：訊息將不攜帶任何資料。</translation>
    </message>
    <message>
        <source>Same as in the drive now.</source>
        <translation>與驅動器目前的設定相同。</translation>
    </message>
    <message>
        <source>Changed: %1 objects, %2 bits (was %3 objects, %4 bits).</source>
        <translation>已變更：%1 個物件，%2 位元（原為 %3 個物件，%4 位元）。</translation>
    </message>
    <message>
        <source> Many drives allow at most 8 objects per PDO.</source>
        <translation> 許多驅動器每個 PDO 最多只允許 8 個物件。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoTimingPage</name>
    <message>
        <source>When the message is sent</source>
        <translation>訊息何時送出</translation>
    </message>
    <message>
        <source>Choose what makes the drive send the message (TPDO) or act on it (RPDO), and the CAN-ID it uses.</source>
        <translation>選擇讓驅動器傳送訊息（TPDO）或處理訊息（RPDO）的觸發條件，以及所使用的 CAN-ID。</translation>
    </message>
    <message>
        <source>On SYNC, every n-th SYNC (synchronous cyclic, type 1–240)</source>
        <translation>依 SYNC，每第 n 個 SYNC（同步週期，類型 1–240）</translation>
    </message>
    <message>
        <source>On SYNC, only after a value changed (synchronous acyclic, type 0)</source>
        <translation>依 SYNC，僅在值變化後（同步非週期，類型 0）</translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 255: device profile)</source>
        <translation>值變化時和／或依計時器（事件觸發，類型 255：裝置子協定）</translation>
    </message>
    <message>
        <source>On change and/or by timer (event-driven, type 254: manufacturer)</source>
        <translation>值變化時和／或依計時器（事件觸發，類型 254：製造商定義）</translation>
    </message>
    <message>
        <source>Other transmission type (e.g. 252/253: only on request, RTR)</source>
        <translation>其他傳輸類型（例如 252/253：僅在請求時，RTR）</translation>
    </message>
    <message>
        <source>every </source>
        <translation>每 </translation>
    </message>
    <message>
        <source> SYNC(s)</source>
        <translation> 個 SYNC</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>off</source>
        <translation>關閉</translation>
    </message>
    <message>
        <source>Message switched on (COB-ID bit 31 = 0: PDO valid)</source>
        <translation>訊息已開啟（COB-ID 位元 31 = 0：PDO 有效）</translation>
    </message>
    <message>
        <source>Default</source>
        <translation>預設值</translation>
    </message>
    <message>
        <source>The pre-defined connection set (CiA 301 §7.3.5): TPDO1 180h + node … RPDO4 500h + node</source>
        <translation>預定義連線組（CiA 301 §7.3.5）：TPDO1 180h + 節點 … RPDO4 500h + 節點</translation>
    </message>
    <message>
        <source>Sent when:</source>
        <translation>傳送時機：</translation>
    </message>
    <message>
        <source>Minimum gap (inhibit time):</source>
        <translation>最小間隔（禁止時間）：</translation>
    </message>
    <message>
        <source>Timer (event timer):</source>
        <translation>計時器（事件計時器）：</translation>
    </message>
    <message>
        <source>This drive fixes the CAN-ID (COB-ID read-only): it cannot be changed, and the message cannot be switched off</source>
        <translation>此驅動器的 CAN-ID 固定（COB-ID 唯讀）：無法變更，訊息也無法關閉</translation>
    </message>
    <message>
        <source>The drive waits at least this long between two messages (100 µs units on the bus)</source>
        <translation>驅動器在兩個訊息之間至少等待這麼久（匯流排上以 100 µs 為單位）</translation>
    </message>
    <message>
        <source>Not available on this drive or for an RPDO</source>
        <translation>此驅動器或 RPDO 不提供此功能</translation>
    </message>
    <message>
        <source>Event-driven TPDO: sent at least this often; RPDO: the drive reports a timeout when no message came for this long</source>
        <translation>事件觸發 TPDO：至少以此頻率送出；RPDO：超過此時間未收到訊息時，驅動器會回報逾時</translation>
    </message>
    <message>
        <source>Not available on this drive</source>
        <translation>此驅動器不提供此功能</translation>
    </message>
    <message>
        <source>Someone must send SYNC (a SYNC producer, object 1005h/1006h) or this message never goes out.</source>
        <translation>必須有設備送出 SYNC（SYNC 產生者，物件 1005h/1006h），否則此訊息永遠不會送出。</translation>
    </message>
    <message>
        <source>The master must send SYNC after the message, every cycle.</source>
        <translation>主站必須在每個週期於訊息之後送出 SYNC。</translation>
    </message>
    <message>
        <source>Event timer off: sent only when a mapped value changes.</source>
        <translation>事件計時器關閉：只有在映射的值變化時才送出。</translation>
    </message>
    <message>
        <source>Sent when a value changes, and at least every %1 ms.</source>
        <translation>值變化時送出，且至少每 %1 ms 送出一次。</translation>
    </message>
    <message>
        <source>Never more often than every %1 ms (inhibit time).</source>
        <translation>送出間隔不短於 %1 ms（禁止時間）。</translation>
    </message>
    <message>
        <source>CAN-ID %1h is not the default %2h: make sure no other message uses it.</source>
        <translation>CAN-ID %1h 不是預設的 %2h：請確認沒有其他訊息使用它。</translation>
    </message>
    <message>
        <source>The message will be switched off: the drive will neither send nor accept it.</source>
        <translation>訊息將被關閉：驅動器既不傳送也不接收它。</translation>
    </message>
    <message>
        <source>AIMOTOR: synchronous PDOs need SYNC from the master.</source>
        <translation>AIMOTOR：同步 PDO 需要主站送出 SYNC。</translation>
    </message>
    <message>
        <source>CAN-ID (COB-ID):</source>
        <translation>CAN-ID (COB-ID)：</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PdoWizard</name>
    <message>
        <source>PDO mapping — CoScope</source>
        <translation>PDO 映射 — CoScope</translation>
    </message>
    <message>
        <source>Not connected to a bus: this wizard talks to the drive, so connect first (File ▸ Connect).</source>
        <translation>未連線到匯流排：此精靈需要與驅動器通訊，請先連線（檔案 ▸ 連線）。</translation>
    </message>
    <message>
        <source>The bus is open listen-only: CoScope never transmits on it, so this wizard can neither read nor change the drive. Reconnect without listen-only to use it.</source>
        <translation>匯流排以僅監聽方式開啟：CoScope 不會在上面傳送，因此此精靈無法讀取或變更驅動器。請取消僅監聽後重新連線再使用。</translation>
    </message>
    <message>
        <source>The bus is not open (yet): wait for it to connect.</source>
        <translation>匯流排（尚）未開啟：請等待連線完成。</translation>
    </message>
    <message>
        <source>the connection changed while reading</source>
        <translation>讀取時連線已變更</translation>
    </message>
    <message>
        <source>The connection was closed while the PDO was being changed. Connect again and read the PDO to see what is in force.</source>
        <translation>變更 PDO 時連線被關閉。請重新連線並讀取 PDO，確認目前生效的設定。</translation>
    </message>
    <message>
        <source>Choose a drive first.</source>
        <translation>請先選擇驅動器。</translation>
    </message>
    <message>
        <source>The PDO has not been read from the drive yet.</source>
        <translation>尚未從驅動器讀取 PDO。</translation>
    </message>
    <message>
        <source>PDO mapping: %1 of node %2</source>
        <translation>PDO 映射：節點 %2 的 %1</translation>
    </message>
    <message>
        <source>Keep the settings after power-off: store all parameters (1010h:01 = &quot;save&quot;, CiA 301 §7.5.2.13)</source>
        <translation>斷電後保留設定：儲存所有參數（1010h:01 = &quot;save&quot;，CiA 301 §7.5.2.13）</translation>
    </message>
    <message>
        <source>Start process data: the drive goes operational and sends/uses its PDOs (NMT start)</source>
        <translation>啟動過程資料：驅動器進入操作狀態並傳送／使用其 PDO（NMT 啟動）</translation>
    </message>
    <message>
        <source>A change is already being applied.</source>
        <translation>已有變更正在套用。</translation>
    </message>
    <message>
        <source>Stopped at step %1 of %2: %3%4.</source>
        <translation>停止於第 %1 步（共 %2 步）：%3%4。</translation>
    </message>
    <message>
        <source>What the drive answered: %1</source>
        <translation>驅動器的回應：%1</translation>
    </message>
    <message>
        <source>What to check: %1</source>
        <translation>檢查事項：%1</translation>
    </message>
    <message>
        <source>The previous settings were written back: %1 works as before (%2 objects, %3 bits). The drive was left pre-operational.</source>
        <translation>已寫回先前的設定：%1 與之前相同（%2 個物件，%3 位元）。驅動器維持在預操作狀態。</translation>
    </message>
    <message>
        <source>Writing the previous settings back failed as well (%1): read the PDO again and check it before starting the drive.</source>
        <translation>寫回先前的設定也失敗了（%1）：啟動驅動器前，請重新讀取 PDO 並檢查。</translation>
    </message>
    <message>
        <source>Nothing was changed on the drive.</source>
        <translation>驅動器上沒有任何變更。</translation>
    </message>
    <message>
        <source>Done: %1 of node %2 now carries %3 objects (%4 bits), checked by reading back. The trace and the plot decode it with the new layout from now on.</source>
        <translation>完成：節點 %2 的 %1 現在攜帶 %3 個物件（%4 位元），已讀回確認。追蹤與圖表從現在起以新的配置解碼。</translation>
    </message>
    <message>
        <source> The drive is pre-operational: start it (NMT start) to make PDOs flow.</source>
        <translation> 驅動器處於預操作狀態：啟動它（NMT 啟動）即可開始傳送 PDO。</translation>
    </message>
    <message>
        <source> Starting the drive failed: %1</source>
        <translation> 啟動驅動器失敗：%1</translation>
    </message>
    <message>
        <source> The drive was started (operational).</source>
        <translation> 驅動器已啟動（操作狀態）。</translation>
    </message>
    <message>
        <source>
But storing failed (%1): the new mapping works now and is lost at power-off. %2</source>
        <translation>
但儲存失敗（%1）：新的映射目前有效，斷電後會遺失。%2</translation>
    </message>
    <message>
        <source> Stored in the drive (kept after power-off).</source>
        <translation> 已儲存到驅動器（斷電後保留）。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotDock</name>
    <message>
        <source>Plot</source>
        <translation>圖表</translation>
    </message>
    <message>
        <source>Rolling window</source>
        <translation>滾動視窗</translation>
    </message>
    <message>
        <source>Whole trace</source>
        <translation>整個追蹤</translation>
    </message>
    <message>
        <source>Follow the newest samples over a window of seconds, or show the whole trace</source>
        <translation>在數秒寬的視窗內跟隨最新的取樣，或顯示整個追蹤</translation>
    </message>
    <message>
        <source> s</source>
        <translation> 秒</translation>
    </message>
    <message>
        <source>Width of the rolling window</source>
        <translation>滾動視窗的寬度</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暫停</translation>
    </message>
    <message>
        <source>Freeze the view (data keeps being recorded); zoom and pan pause too</source>
        <translation>凍結畫面（資料仍持續記錄）；縮放與平移也會暫停</translation>
    </message>
    <message>
        <source>Stacked</source>
        <translation>堆疊</translation>
    </message>
    <message>
        <source>Shared plot</source>
        <translation>共用圖表</translation>
    </message>
    <message>
        <source>Stacked plots sharing the time axis, or one plot with a y-axis per signal</source>
        <translation>共用時間軸的堆疊圖表，或每個訊號各有一條 Y 軸的單一圖表</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>自動縮放</translation>
    </message>
    <message>
        <source>Fit the y-axes to the visible data</source>
        <translation>將 Y 軸調整為符合可見資料</translation>
    </message>
    <message>
        <source>Auto Y</source>
        <translation>自動 Y</translation>
    </message>
    <message>
        <source>Keep the y-axes fitted; off: drag and wheel zoom the y-axes too</source>
        <translation>持續自動調整 Y 軸；關閉時：拖曳與滾輪也會縮放 Y 軸</translation>
    </message>
    <message>
        <source>Legend</source>
        <translation>圖例</translation>
    </message>
    <message>
        <source>Clear cursors</source>
        <translation>清除游標</translation>
    </message>
    <message>
        <source>Add raw signal…</source>
        <translation>加入原始訊號…</translation>
    </message>
    <message>
        <source>Plot bits of any frame (start bit, length, type, byte order, factor, offset, unit): for devices without a dictionary</source>
        <translation>繪製任何封包的位元（起始位元、長度、類型、位元組順序、係數、偏移、單位）：適用於沒有字典的裝置</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>匯出</translation>
    </message>
    <message>
        <source>PNG image…</source>
        <translation>PNG 圖片…</translation>
    </message>
    <message>
        <source>PDF document…</source>
        <translation>PDF 文件…</translation>
    </message>
    <message>
        <source>CSV of the visible window…</source>
        <translation>可見視窗的 CSV…</translation>
    </message>
    <message>
        <source>Resume</source>
        <translation>繼續</translation>
    </message>
    <message>
        <source>No frames from the bus yet.</source>
        <translation>尚未從匯流排收到封包。</translation>
    </message>
    <message>
        <source>Reading the log…</source>
        <translation>正在讀取記錄檔…</translation>
    </message>
    <message>
        <source>The log holds no frames.</source>
        <translation>記錄檔中沒有封包。</translation>
    </message>
    <message>
        <source>Nothing to plot: connect to a bus (Bus menu) or open a log (File ▸ Open log…).</source>
        <translation>沒有可繪製的內容：請連線到匯流排（匯流排選單）或開啟記錄檔（檔案 ▸ 開啟記錄檔…）。</translation>
    </message>
    <message>
        <source>bus %1 node %2</source>
        <translation>匯流排 %1 節點 %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>No PDOs in this trace (%L1 frames): the plot shows the objects that PDOs carry.</source>
        <translation>此追蹤中沒有 PDO（%L1 個封包）：圖表顯示的是 PDO 所攜帶的物件。</translation>
    </message>
    <message>
        <source>Nodes seen: %1.</source>
        <translation>已看到的節點：%1。</translation>
    </message>
    <message>
        <source>Nodes send their PDOs once started (Nodes dock: right-click ▸ Start).</source>
        <translation>節點啟動後才會傳送 PDO（節點面板：按右鍵 ▸ 啟動）。</translation>
    </message>
    <message>
        <source>No dictionary for these nodes, so their PDOs cannot be decoded: %1. Assign one in the Nodes dock (right-click the node ▸ Assign dictionary…)%2; its PDO signals are then listed here.</source>
        <translation>這些節點沒有字典，因此無法解碼其 PDO：%1。請在節點面板中指定字典（在節點上按右鍵 ▸ 指定字典…）%2；之後其 PDO 訊號就會列在這裡。</translation>
    </message>
    <message>
        <source> or identify the nodes with Bus ▸ Scan network</source>
        <translation> 或以「匯流排 ▸ 掃描網路」識別節點</translation>
    </message>
    <message>
        <source>PDOs whose mapping is not known (changed before the trace began): %1.</source>
        <translation>映射未知的 PDO（在追蹤開始前已變更）：%1。</translation>
    </message>
    <message>
        <source>Raw signal %1 added: it is listed under COB-ID %2h once its frames are read</source>
        <translation>已加入原始訊號 %1：讀到其封包後，會列在 COB-ID %2h 之下</translation>
    </message>
    <message>
        <source>%1: cannot write the PNG image</source>
        <translation>%1：無法寫入 PNG 圖片</translation>
    </message>
    <message>
        <source>%1: cannot write the PDF document</source>
        <translation>%1：無法寫入 PDF 文件</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG 圖片（*.png）</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文件（*.pdf）</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV（*.csv）</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>匯出圖表</translation>
    </message>
    <message>
        <source>Plot exported to %1</source>
        <translation>圖表已匯出至 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::PlotView</name>
    <message>
        <source>Pick signals on the left</source>
        <translation>請在左側選擇訊號</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>時間 [s]</translation>
    </message>
    <message>
        <source>Click the plot to place cursor A (jumps to the frame), Shift+click for cursor B.</source>
        <translation>按一下圖表可放置游標 A（並跳至該封包），Shift+按一下放置游標 B。</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>時間</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProcessDataDock</name>
    <message>
        <source>Switch on</source>
        <translation>啟動（Switch on）</translation>
    </message>
    <message>
        <source>Enable voltage</source>
        <translation>電壓致能（Enable voltage）</translation>
    </message>
    <message>
        <source>Quick stop (0 = active)</source>
        <translation>快速停止（Quick Stop，0 = 作用中）</translation>
    </message>
    <message>
        <source>Enable operation</source>
        <translation>運轉致能（Enable operation）</translation>
    </message>
    <message>
        <source>New set-point</source>
        <translation>新設定點（New set-point）</translation>
    </message>
    <message>
        <source>Change set immediately</source>
        <translation>立即變更設定（Change set immediately）</translation>
    </message>
    <message>
        <source>Relative</source>
        <translation>相對（Relative）</translation>
    </message>
    <message>
        <source>Fault reset</source>
        <translation>故障重置</translation>
    </message>
    <message>
        <source>Halt</source>
        <translation>暫停（Halt）</translation>
    </message>
    <message>
        <source>Process data</source>
        <translation>過程資料</translation>
    </message>
    <message>
        <source>Node:</source>
        <translation>節點：</translation>
    </message>
    <message>
        <source>Send once</source>
        <translation>傳送一次</translation>
    </message>
    <message>
        <source>On change</source>
        <translation>變更時傳送</translation>
    </message>
    <message>
        <source>Every N ms</source>
        <translation>每 N ms</translation>
    </message>
    <message>
        <source>With each SYNC</source>
        <translation>隨每個 SYNC</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>啟動</translation>
    </message>
    <message>
        <source>Send</source>
        <translation>傳送</translation>
    </message>
    <message>
        <source>Arm motion…</source>
        <translation>準備運轉…</translation>
    </message>
    <message>
        <source>Hold to run</source>
        <translation>按住運轉</translation>
    </message>
    <message>
        <source>RPDOs with motion objects are sent only while this button is held down; releasing it sends halt and velocity 0.</source>
        <translation>含運動物件的 RPDO 只在按住此按鈕時傳送；放開時傳送暫停（Halt）與速度 0。</translation>
    </message>
    <message>
        <source>Hold to run was not fed: the drive was sent halt and velocity 0.</source>
        <translation>「按住運轉」未持續按住：已對驅動器傳送暫停（Halt）與速度 0。</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Node %1: its dictionary %2 could not be loaded: %3</source>
        <translation>節點 %1：無法載入其物件字典 %2：%3</translation>
    </message>
    <message>
        <source>Could not read: %1</source>
        <translation>無法讀取：%1</translation>
    </message>
    <message>
        <source>RPDO%1 (%2h)</source>
        <translation>RPDO%1（%2h）</translation>
    </message>
    <message>
        <source>%1 (bit %2)</source>
        <translation>%1（bit %2）</translation>
    </message>
    <message>
        <source>Decimal, 0x1F or 1Fh</source>
        <translation>十進位、0x1F 或 1Fh</translation>
    </message>
    <message>
        <source>In %1</source>
        <translation>單位 %1</translation>
    </message>
    <message>
        <source>TPDOs: no values seen yet (are they sent on SYNC?)</source>
        <translation>TPDO：尚未收到數值（是否在 SYNC 時才傳送？）</translation>
    </message>
    <message>
        <source>TPDOs: %1</source>
        <translation>TPDO：%1</translation>
    </message>
    <message>
        <source>No bus is connected.</source>
        <translation>未連線任何匯流排。</translation>
    </message>
    <message>
        <source>The bus is listen-only or not open: nothing can be sent.</source>
        <translation>匯流排為僅監聽或未開啟：無法傳送。</translation>
    </message>
    <message>
        <source>The bus&apos;s master services are not available.</source>
        <translation>此匯流排的主站服務無法使用。</translation>
    </message>
    <message>
        <source>No node with a dictionary is known yet: scan the network or assign a dictionary.</source>
        <translation>尚無已知且有物件字典的節點：請掃描網路或指定物件字典。</translation>
    </message>
    <message>
        <source>This node&apos;s dictionary maps no RPDO.</source>
        <translation>此節點的物件字典沒有映射任何 RPDO。</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Sent with each SYNC: start the SYNC producer (Bus menu) for frames to go out.</source>
        <translation>隨每個 SYNC 傳送：請啟動 SYNC 產生器（匯流排選單）才會送出封包。</translation>
    </message>
    <message>
        <source>Sent.</source>
        <translation>已傳送。</translation>
    </message>
    <message>
        <source>Arm motion</source>
        <translation>準備運轉</translation>
    </message>
    <message>
        <source>The RPDOs of node %1 carry motion objects (controlword, mode, targets). While &quot;Hold to run&quot; is held, they are sent with the values shown and the motor can move. Releasing the button sends halt and velocity 0.

Make sure the axis is free to move. Arm?</source>
        <translation>節點 %1 的 RPDO 含運動物件（控制字、模式、目標值）。按住「按住運轉」時會以顯示的數值傳送，馬達可能轉動。放開按鈕時傳送暫停（Halt）與速度 0。

請確認軸可以自由移動。要準備運轉嗎？</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProgramDownloadDialog</name>
    <message>
        <source>Download program to node %1</source>
        <translation>下載程式到節點 %1</translation>
    </message>
    <message>
        <source>Program image file</source>
        <translation>程式映像檔</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>瀏覽…</translation>
    </message>
    <message>
        <source>Program file:</source>
        <translation>程式檔案：</translation>
    </message>
    <message>
        <source>The program number: sub-index of 1F50h program data and 1F51h program control (CiA 302-3)</source>
        <translation>程式編號：1F50h 程式資料與 1F51h 程式控制的子索引（CiA 302-3）</translation>
    </message>
    <message>
        <source>Program number:</source>
        <translation>程式編號：</translation>
    </message>
    <message>
        <source>Block transfer (segmented when the node declines it)</source>
        <translation>區塊傳輸（節點不支援時改用分段傳輸）</translation>
    </message>
    <message>
        <source>Start the program after the download (the node resets)</source>
        <translation>下載後啟動程式（節點會重置）</translation>
    </message>
    <message>
        <source>What the node reports now</source>
        <translation>節點目前回報的內容</translation>
    </message>
    <message>
        <source>Software version (100Ah):</source>
        <translation>軟體版本（100Ah）：</translation>
    </message>
    <message>
        <source>Software identification (1F56h):</source>
        <translation>軟體識別碼（1F56h）：</translation>
    </message>
    <message>
        <source>Flash status (1F57h):</source>
        <translation>快閃記憶體狀態（1F57h）：</translation>
    </message>
    <message>
        <source>Read again</source>
        <translation>重新讀取</translation>
    </message>
    <message>
        <source>Download</source>
        <translation>下載</translation>
    </message>
    <message>
        <source>Cancel download</source>
        <translation>取消下載</translation>
    </message>
    <message>
        <source>Program image for node %1</source>
        <translation>節點 %1 的程式映像檔</translation>
    </message>
    <message>
        <source>Program images (*.img *.bin *.hex);;All files (*)</source>
        <translation>程式映像檔 (*.img *.bin *.hex);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>The bus was closed: nothing is claimed about the node&apos;s program.</source>
        <translation>匯流排已關閉：不對節點的程式做任何保證。</translation>
    </message>
    <message>
        <source>Listen-only bus: a program download would transmit</source>
        <translation>僅監聽匯流排：程式下載需要發送訊息</translation>
    </message>
    <message>
        <source>Connect to a bus first</source>
        <translation>請先連線到匯流排</translation>
    </message>
    <message>
        <source>not read</source>
        <translation>未讀取</translation>
    </message>
    <message>
        <source>Download again (from the start)</source>
        <translation>重新下載（從頭開始）</translation>
    </message>
    <message>
        <source>Node %1 stops its application for the download (1F51h = 0): a motor it drives is not controlled until the new program has started.</source>
        <translation>節點 %1 下載期間會停止其應用程式（1F51h = 0）：在新程式啟動前，它所驅動的馬達不受控制。</translation>
    </message>
    <message>
        <source>CoScope enabled %1: it is disabled first (6040h = 0).</source>
        <translation>CoScope 已致能 %1：會先將其切斷電壓（6040h = 0）。</translation>
    </message>
    <message>
        <source>reading…</source>
        <translation>讀取中…</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>無回應</translation>
    </message>
    <message>
        <source>Reading the program state (1F56h, 1F57h, 100Ah)</source>
        <translation>讀取程式狀態（1F56h、1F57h、100Ah）</translation>
    </message>
    <message>
        <source>Disabling the drive (6040h = 0)</source>
        <translation>切斷驅動器電壓（6040h = 0）</translation>
    </message>
    <message>
        <source>Stopping the program (1F51h:%1 = 0)</source>
        <translation>停止程式（1F51h:%1 = 0）</translation>
    </message>
    <message>
        <source>Clearing the program (1F51h:%1 = 3)</source>
        <translation>清除程式（1F51h:%1 = 3）</translation>
    </message>
    <message>
        <source>Downloading the program data (1F50h:%1)</source>
        <translation>下載程式資料（1F50h:%1）</translation>
    </message>
    <message>
        <source>Starting the program (1F51h:%1 = 1)</source>
        <translation>啟動程式（1F51h:%1 = 1）</translation>
    </message>
    <message>
        <source>Waiting for the node&apos;s boot-up</source>
        <translation>等待節點的上線訊息</translation>
    </message>
    <message>
        <source>Reading the new program state</source>
        <translation>讀取新程式狀態</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>larger than 16 MiB</source>
        <translation>大於 16 MiB</translation>
    </message>
    <message>
        <source>Cannot read %1: %2</source>
        <translation>無法讀取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is empty.</source>
        <translation>%1 是空的。</translation>
    </message>
    <message>
        <source>Download %1 (%2 bytes) into program %3 of node %4?</source>
        <translation>要將 %1（%2 位元組）下載到節點 %4 的程式 %3 嗎？</translation>
    </message>
    <message>
        <source>The node stops its application (1F51h = 0) and its program is replaced. If the download fails, the node may have no valid program until a download succeeds.</source>
        <translation>節點會停止其應用程式（1F51h = 0），其程式將被取代。若下載失敗，在下載成功之前節點可能沒有有效的程式。</translation>
    </message>
    <message>
        <source>CoScope disables %1 first (6040h = 0).</source>
        <translation>CoScope 會先切斷 %1 的電壓（6040h = 0）。</translation>
    </message>
    <message>
        <source>Then the node starts the new program and resets (boot-up).</source>
        <translation>接著節點會啟動新程式並重置（上線訊息）。</translation>
    </message>
    <message>
        <source>%L1 of %L2 bytes, %L3 KiB/s</source>
        <translation>%L1 / %L2 位元組，%L3 KiB/s</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Done: node %1 runs the new program. Software version %2 → %3, software identification %4 → %5.</source>
        <translation>完成：節點 %1 正在執行新程式。軟體版本 %2 → %3，軟體識別碼 %4 → %5。</translation>
    </message>
    <message>
        <source>Downloaded; the program was not started (node %1 stays stopped).</source>
        <translation>已下載；程式未啟動（節點 %1 保持停止）。</translation>
    </message>
    <message>
        <source>%L1 bytes in %L2 s.</source>
        <translation>%L1 位元組，耗時 %L2 秒。</translation>
    </message>
    <message>
        <source>The node&apos;s program was not touched.</source>
        <translation>節點的程式未被更動。</translation>
    </message>
    <message>
        <source>Nothing is claimed: the node may hold no valid program. Download again to start over from the beginning.</source>
        <translation>不做任何保證：節點可能沒有有效的程式。請重新下載，從頭開始。</translation>
    </message>
    <message>
        <source>Cancelled at “%1”: %2</source>
        <translation>已在「%1」取消：%2</translation>
    </message>
    <message>
        <source>Failed at “%1”: %2</source>
        <translation>在「%1」失敗：%2</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProjectActions</name>
    <message>
        <source>CoScope projects (*.coscope *.coscope.json);;All files (*)</source>
        <translation>CoScope 專案 (*.coscope *.coscope.json);;所有檔案 (*)</translation>
    </message>
    <message>
        <source>&amp;New project</source>
        <translation>新增專案(&amp;N)</translation>
    </message>
    <message>
        <source>Open &amp;project…</source>
        <translation>開啟專案(&amp;P)…</translation>
    </message>
    <message>
        <source>Open project</source>
        <translation>開啟專案</translation>
    </message>
    <message>
        <source>Save pro&amp;ject</source>
        <translation>儲存專案(&amp;J)</translation>
    </message>
    <message>
        <source>Save project &amp;as…</source>
        <translation>專案另存為(&amp;A)…</translation>
    </message>
    <message>
        <source>Recent pro&amp;jects</source>
        <translation>最近的專案(&amp;J)</translation>
    </message>
    <message>
        <source>&amp;Project</source>
        <translation>專案(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Compare with the machine…</source>
        <translation>與機台比較(&amp;C)…</translation>
    </message>
    <message>
        <source>&amp;Back up the machine</source>
        <translation>備份機台(&amp;B)</translation>
    </message>
    <message>
        <source>&amp;Apply the project…</source>
        <translation>套用專案(&amp;A)…</translation>
    </message>
    <message>
        <source>Unsaved project</source>
        <translation>專案未儲存</translation>
    </message>
    <message>
        <source>The project &quot;%1&quot; has changes that are not saved. Save the project first?</source>
        <translation>專案「%1」有尚未儲存的變更。要先儲存專案嗎？</translation>
    </message>
    <message>
        <source>New project: Project ▸ Back up the machine reads the drives into it</source>
        <translation>新專案：專案 ▸ 備份機台 會把驅動器讀入專案</translation>
    </message>
    <message>
        <source>Project %1 opened</source>
        <translation>已開啟專案 %1</translation>
    </message>
    <message>
        <source>Connect to the project&apos;s bus %1?</source>
        <translation>要連線到專案的匯流排 %1 嗎？</translation>
    </message>
    <message>
        <source>Save project</source>
        <translation>儲存專案</translation>
    </message>
    <message>
        <source>Project saved to %1</source>
        <translation>專案已儲存到 %1</translation>
    </message>
    <message>
        <source>Back up the machine</source>
        <translation>備份機台</translation>
    </message>
    <message>
        <source>Connect to the machine&apos;s bus first (not listen-only): the backup reads the drives.</source>
        <translation>請先連線到機台的匯流排（非僅監聽）：備份會讀取驅動器。</translation>
    </message>
    <message>
        <source>Backing up the machine: reading every drive…</source>
        <translation>正在備份機台：讀取每台驅動器…</translation>
    </message>
    <message>
        <source>Backing up the machine: %1</source>
        <translation>正在備份機台：%1</translation>
    </message>
    <message>
        <source>Node %1: %2</source>
        <translation>節點 %1：%2</translation>
    </message>
    <message>
        <source>Node %1: NOT backed up: %2</source>
        <translation>節點 %1：未備份：%2</translation>
    </message>
    <message numerus="yes">
        <source>Backup done: %n node(s)</source>
        <translation>
            <numerusform>備份完成：%n 個節點</numerusform>
        </translation>
    </message>
    <message>
        <source>The drives&apos; configuration is in the project; save the project to keep it.</source>
        <translation>驅動器的設定已在專案中；請儲存專案以保留。</translation>
    </message>
    <message>
        <source>Download the project&apos;s program…</source>
        <translation>下載專案的程式…</translation>
    </message>
    <message>
        <source>Load the program (firmware) the project names for the selected node: CiA 302-3 program download</source>
        <translation>為選取的節點載入專案指定的程式（韌體）：CiA 302-3 程式下載</translation>
    </message>
    <message>
        <source>The bus closed before the backup was finished: the project is as it was.</source>
        <translation>備份完成前匯流排已關閉：專案維持原樣。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ProjectSession</name>
    <message>
        <source>Untitled project</source>
        <translation>未命名專案</translation>
    </message>
</context>
<context>
    <name>coscope::gui::RawSignalDialog</name>
    <message>
        <source>Add raw signal</source>
        <translation>加入原始訊號</translation>
    </message>
    <message>
        <source>0x181</source>
        <translation>0x181</translation>
    </message>
    <message>
        <source>The frame&apos;s identifier: decimal or 0x hex; over 7FFh a 29-bit identifier</source>
        <translation>封包的識別碼：十進位或 0x 十六進位；大於 7FFh 為 29 位元識別碼</translation>
    </message>
    <message>
        <source>Intel: the least significant bit; Motorola: the most significant bit (DBC numbering, bit 7 of byte 0 = 7)</source>
        <translation>Intel：最低有效位元；Motorola：最高有效位元（DBC 編號方式，位元組 0 的位元 7 = 7）</translation>
    </message>
    <message>
        <source> bits</source>
        <translation> 位元</translation>
    </message>
    <message>
        <source>Unsigned</source>
        <translation>無號</translation>
    </message>
    <message>
        <source>Signed</source>
        <translation>有號</translation>
    </message>
    <message>
        <source>Float (IEEE 754, 32 or 64 bits)</source>
        <translation>浮點數（IEEE 754，32 或 64 位元）</translation>
    </message>
    <message>
        <source>Intel (little-endian, as CANopen PDOs)</source>
        <translation>Intel（小端序，與 CANopen PDO 相同）</translation>
    </message>
    <message>
        <source>Motorola (big-endian)</source>
        <translation>Motorola（大端序）</translation>
    </message>
    <message>
        <source>value = raw × factor + offset</source>
        <translation>值 = 原始值 × 係數 + 偏移</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>名稱</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>Start bit</source>
        <translation>起始位元</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>長度</translation>
    </message>
    <message>
        <source>Type</source>
        <translation>類型</translation>
    </message>
    <message>
        <source>Byte order</source>
        <translation>位元組順序</translation>
    </message>
    <message>
        <source>Factor</source>
        <translation>係數</translation>
    </message>
    <message>
        <source>Offset</source>
        <translation>偏移</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <source>Plot bits of any frame, for a device without a dictionary.</source>
        <translation>繪製任何封包的位元，適用於沒有字典的裝置。</translation>
    </message>
    <message>
        <source>Give the signal a name.</source>
        <translation>請為訊號命名。</translation>
    </message>
    <message>
        <source>The COB-ID must be a number up to 1FFFFFFFh (0x181, 385 or 181h).</source>
        <translation>COB-ID 必須是不超過 1FFFFFFFh 的數字（0x181、385 或 181h）。</translation>
    </message>
    <message>
        <source>The factor must be a number other than 0.</source>
        <translation>係數必須是不為 0 的數字。</translation>
    </message>
    <message>
        <source>The offset must be a number.</source>
        <translation>偏移必須是數字。</translation>
    </message>
    <message>
        <source>A float is 32 or 64 bits long.</source>
        <translation>浮點數長度為 32 或 64 位元。</translation>
    </message>
    <message>
        <source>The signal ends past byte 64 of the frame.</source>
        <translation>訊號結束位置超出封包的第 64 位元組。</translation>
    </message>
    <message>
        <source>This signal cannot be read: %1.</source>
        <translation>無法讀取此訊號：%1。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::RecentFilesMenu</name>
    <message>
        <source>%1 (not found)</source>
        <translation>%1（找不到）</translation>
    </message>
    <message>
        <source>%1 no longer exists</source>
        <translation>%1 已不存在</translation>
    </message>
    <message>
        <source>Clear recent</source>
        <translation>清除最近項目</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptPreview</name>
    <message>
        <source>What it does</source>
        <translation>用途</translation>
    </message>
    <message>
        <source>Script line</source>
        <translation>腳本行</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>原因</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>結果</translation>
    </message>
    <message>
        <source>Save as script…</source>
        <translation>另存為腳本…</translation>
    </message>
    <message>
        <source>Write these steps to a text file that `coscope-cli script run BUS FILE` replays</source>
        <translation>將這些步驟寫入文字檔，可用 `coscope-cli script run BUS FILE` 重播</translation>
    </message>
    <message numerus="yes">
        <source>%n step(s) will be sent</source>
        <translation>
            <numerusform>將送出 %n 個步驟</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 — %n step(s)</source>
        <translation>
            <numerusform>%1 — %n 個步驟</numerusform>
        </translation>
    </message>
    <message>
        <source>done</source>
        <translation>完成</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失敗</translation>
    </message>
    <message>
        <source>running…</source>
        <translation>執行中…</translation>
    </message>
    <message>
        <source>Save as script</source>
        <translation>另存為腳本</translation>
    </message>
    <message>
        <source>Command scripts (*.txt);;All files (*)</source>
        <translation>指令腳本（*.txt）;;所有檔案（*）</translation>
    </message>
    <message>
        <source>Could not save the script: %1</source>
        <translation>無法儲存腳本：%1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::ScriptRunPanel</name>
    <message>
        <source>Run</source>
        <translation>執行</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>停止</translation>
    </message>
    <message>
        <source>Stopped: the connection changed.</source>
        <translation>已停止：連線已變更。</translation>
    </message>
    <message>
        <source>Send these commands?</source>
        <translation>要送出這些指令嗎？</translation>
    </message>
    <message>
        <source>A run is in progress.</source>
        <translation>正在執行中。</translation>
    </message>
    <message>
        <source>The bus cannot send now.</source>
        <translation>匯流排目前無法傳送。</translation>
    </message>
    <message>
        <source>Step %1 of %2…</source>
        <translation>第 %1 步（共 %2 步）…</translation>
    </message>
    <message numerus="yes">
        <source>Done: %n step(s) completed.</source>
        <translation>
            <numerusform>完成：已完成 %n 個步驟。</numerusform>
        </translation>
    </message>
    <message>
        <source>Stopped at step %1; nothing further was sent.</source>
        <translation>停止於第 %1 步；之後沒有再送出任何內容。</translation>
    </message>
    <message>
        <source>Failed at %1</source>
        <translation>失敗於 %1</translation>
    </message>
</context>
<context>
    <name>coscope::gui::SignalPicker</name>
    <message>
        <source>Search signals (name, object, node)</source>
        <translation>搜尋訊號（名稱、物件、節點）</translation>
    </message>
    <message>
        <source>Signal</source>
        <translation>訊號</translation>
    </message>
    <message>
        <source>Object</source>
        <translation>物件</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>單位</translation>
    </message>
    <message>
        <source>Factor</source>
        <translation>係數</translation>
    </message>
    <message>
        <source>No signal matches “%1”.</source>
        <translation>沒有符合「%1」的訊號。</translation>
    </message>
    <message>
        <source>Bus %1, COB-ID %2h (raw signals)</source>
        <translation>匯流排 %1，COB-ID %2h（原始訊號）</translation>
    </message>
    <message>
        <source>COB-ID %1h (raw signals)</source>
        <translation>COB-ID %1h（原始訊號）</translation>
    </message>
    <message>
        <source>Bus %1, node %2</source>
        <translation>匯流排 %1，節點 %2</translation>
    </message>
    <message>
        <source>Node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>value = raw × factor + %1 (defined: × %2 %3)</source>
        <translation>值 = 原始值 × 係數 + %1（定義：× %2 %3）</translation>
    </message>
    <message>
        <source>value = raw × factor (dictionary: %1 %2)</source>
        <translation>值 = 原始值 × 係數（字典：%1 %2）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceDock</name>
    <message>
        <source>Trace</source>
        <translation>追蹤</translation>
    </message>
    <message>
        <source>Close this report</source>
        <translation>關閉此報告</translation>
    </message>
    <message>
        <source>Follow</source>
        <translation>跟隨</translation>
    </message>
    <message>
        <source>Follow new frames (scrolling up pauses)</source>
        <translation>跟隨新封包（向上捲動時暫停）</translation>
    </message>
    <message>
        <source>Absolute time</source>
        <translation>絕對時間</translation>
    </message>
    <message>
        <source>Relative time</source>
        <translation>相對時間</translation>
    </message>
    <message>
        <source>Delta time</source>
        <translation>時間差</translation>
    </message>
    <message>
        <source>Latest per ID</source>
        <translation>每個 ID 最新封包</translation>
    </message>
    <message>
        <source>One row per COB-ID showing its latest frame</source>
        <translation>每個 COB-ID 一列，顯示其最新封包</translation>
    </message>
    <message>
        <source>Group SDO</source>
        <translation>SDO 分組</translation>
    </message>
    <message>
        <source>Group SDO transfers: each transfer as one row; click its ▸ to show its frames</source>
        <translation>將 SDO 傳輸分組：每次傳輸顯示為一列；按一下 ▸ 顯示其封包</translation>
    </message>
    <message>
        <source>Filter: node:5 svc:sdo,emcy id:580-5FF text</source>
        <translation>篩選：node:5 svc:sdo,emcy id:580-5FF 文字</translation>
    </message>
    <message>
        <source>Find</source>
        <translation>尋找</translation>
    </message>
    <message>
        <source>Previous</source>
        <translation>上一個</translation>
    </message>
    <message>
        <source>Find previous</source>
        <translation>尋找上一個</translation>
    </message>
    <message>
        <source>Next</source>
        <translation>下一個</translation>
    </message>
    <message>
        <source>Find next</source>
        <translation>尋找下一個</translation>
    </message>
    <message>
        <source>Bookmark</source>
        <translation>書籤</translation>
    </message>
    <message>
        <source>Toggle a bookmark on the selected frame (Ctrl+B); F2 / Shift+F2 jump</source>
        <translation>在選取的封包上切換書籤（Ctrl+B）；F2 / Shift+F2 跳轉</translation>
    </message>
    <message>
        <source>%L1 rows, %L2 frames</source>
        <translation>%L1 列，%L2 個封包</translation>
    </message>
    <message>
        <source>%L1 SDO transfers grouped</source>
        <translation>已將 %L1 個 SDO 傳輸分組</translation>
    </message>
    <message>
        <source>%L1 of %L2 frames</source>
        <translation>%L1／%L2 個封包</translation>
    </message>
    <message>
        <source>%L1 frames</source>
        <translation>%L1 個封包</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found: the trace is empty</source>
        <translation>找不到「%1」：追蹤為空</translation>
    </message>
    <message>
        <source>&apos;%1&apos; not found</source>
        <translation>找不到「%1」</translation>
    </message>
    <message>
        <source>Select a frame to bookmark</source>
        <translation>請選擇要加書籤的封包</translation>
    </message>
    <message>
        <source>No bookmarks (Ctrl+B sets one)</source>
        <translation>沒有書籤（按 Ctrl+B 設定）</translation>
    </message>
    <message>
        <source>Next bookmark</source>
        <translation>下一個書籤</translation>
    </message>
    <message>
        <source>Previous bookmark</source>
        <translation>上一個書籤</translation>
    </message>
    <message>
        <source>The project&apos;s trace filter is not valid: %1</source>
        <translation>專案的追蹤篩選條件無效：%1</translation>
    </message>
    <message>
        <source>How times are shown, here and in the Events, Health and Plot docks: the wall clock (from the log&apos;s header or the capture), seconds since the first frame, or since the row before (this table only)</source>
        <translation>時間的顯示方式（此處以及事件、健康狀態與圖表面板）：實際時鐘時間（取自記錄檔的標頭或擷取時）、自第一個封包起的秒數，或與上一列的時間差（僅此表格）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TraceModel</name>
    <message>
        <source>loading…</source>
        <extracomment>Trace row whose frame is being read back from the capture journal on disk</extracomment>
        <translation>載入中…</translation>
    </message>
    <message>
        <source>Click to expand or collapse the transfer&apos;s frames</source>
        <translation>按一下可展開或收合此傳輸的封包</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>時間</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>時間（秒）</translation>
    </message>
    <message>
        <source>Δt (s)</source>
        <extracomment>Trace column: time since the previous frame, in seconds</extracomment>
        <translation>Δt（秒）</translation>
    </message>
    <message>
        <source>No.</source>
        <extracomment>Trace columns: frame number, time, bus, COB-ID, node, CANopen service, direction (Rx/Tx), data length, data bytes, decoded summary</extracomment>
        <translation>編號</translation>
    </message>
    <message>
        <source>Bus</source>
        <translation>匯流排</translation>
    </message>
    <message>
        <source>COB-ID</source>
        <translation>COB-ID</translation>
    </message>
    <message>
        <source>Node</source>
        <translation>節點</translation>
    </message>
    <message>
        <source>Service</source>
        <translation>服務</translation>
    </message>
    <message>
        <source>Dir</source>
        <translation>方向</translation>
    </message>
    <message>
        <source>Len</source>
        <translation>長度</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Summary</source>
        <translation>摘要</translation>
    </message>
    <message>
        <source>Bus lost at %1, back at %2 (%3 s without frames)</source>
        <translation>匯流排於 %1 中斷，%2 恢復（%3 秒沒有封包）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TransmitDock</name>
    <message>
        <source>Transmit</source>
        <translation>發送</translation>
    </message>
    <message>
        <source>Frame in candump syntax, e.g. 601#4018100100000000, 123#R, 123##1AABB (CAN FD)</source>
        <translation>candump 語法的封包，例如 601#4018100100000000、123#R、123##1AABB（CAN FD）</translation>
    </message>
    <message>
        <source>every</source>
        <translation>每</translation>
    </message>
    <message>
        <source>once</source>
        <translation>一次</translation>
    </message>
    <message>
        <source>Period in ms, to the microsecond (0.5 = 500 µs); empty or 0 = sent once only</source>
        <translation>週期（ms），精確到微秒（0.5 = 500 µs）；空白或 0 = 只發送一次</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>加入</translation>
    </message>
    <message>
        <source>Add the frame to the list without sending it</source>
        <translation>將封包加入清單，但不發送</translation>
    </message>
    <message>
        <source>Add and send</source>
        <translation>加入並發送</translation>
    </message>
    <message>
        <source>Add the frame to the list and send it (Enter)</source>
        <translation>將封包加入清單並發送（Enter）</translation>
    </message>
    <message>
        <source>Send selected</source>
        <translation>發送選取項</translation>
    </message>
    <message>
        <source>Send the selected rows once (Enter in the list)</source>
        <translation>將選取的列各發送一次（在清單中按 Enter）</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Remove the selected rows (Delete)</source>
        <translation>移除選取的列（Delete）</translation>
    </message>
    <message>
        <source>Stop all</source>
        <translation>全部停止</translation>
    </message>
    <message>
        <source>Stop every periodic row</source>
        <translation>停止所有週期發送的列</translation>
    </message>
    <message>
        <source>Every periodic frame stopped</source>
        <translation>所有週期封包已停止</translation>
    </message>
    <message>
        <source>Connect to a bus first: the frames below are kept and sent once a bus is open.</source>
        <translation>請先連線到匯流排：下列封包會保留，匯流排開啟後即可發送。</translation>
    </message>
    <message>
        <source>Listen-only connection: CoScope sends nothing, so the transmit list is disabled.</source>
        <translation>僅監聽連線：CoScope 不發送任何封包，因此發送清單已停用。</translation>
    </message>
    <message>
        <source>The bus is not open: nothing can be sent now.</source>
        <translation>匯流排未開啟：目前無法發送。</translation>
    </message>
    <message numerus="yes">
        <source>%n periodic frame(s) running</source>
        <translation>
            <numerusform>%n 個週期封包正在發送</numerusform>
        </translation>
    </message>
    <message>
        <source>Cannot read “%1”: %2</source>
        <translation>無法解讀「%1」：%2</translation>
    </message>
    <message>
        <source>“%1” is not a period in ms (0 = once only, at least 0.1 ms)</source>
        <translation>「%1」不是以 ms 為單位的週期（0 = 只發送一次，至少 0.1 ms）</translation>
    </message>
    <message>
        <source>Not sent: %1</source>
        <translation>未發送：%1</translation>
    </message>
    <message>
        <source>Give the row a period (Every, ms) to send it periodically</source>
        <translation>請為此列設定週期（每，ms）才能週期發送</translation>
    </message>
    <message>
        <source>Cannot send periodically: %1</source>
        <translation>無法週期發送：%1</translation>
    </message>
    <message>
        <source>It is RPDO%1 of node %2, which carries %3: it can make the motor move.</source>
        <translation>這是節點 %2 的 RPDO%1，其中帶有 %3：可能使馬達運轉。</translation>
    </message>
    <message>
        <source>It is RPDO%1 of node %2, a drive whose mapping CoScope does not know: it can make the motor move.</source>
        <translation>這是節點 %2 的 RPDO%1，此驅動器的映射 CoScope 不知道：可能使馬達運轉。</translation>
    </message>
    <message>
        <source>Send a motion command?</source>
        <translation>要發送運動命令嗎？</translation>
    </message>
    <message>
        <source>%1

Send %2%3?</source>
        <translation>%1

要發送 %2%3 嗎？</translation>
    </message>
    <message>
        <source> every %1 ms</source>
        <translation>（每 %1 ms）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::TransmitModel</name>
    <message>
        <source>Send every %1 ms while checked</source>
        <translation>勾選時每 %1 ms 發送一次</translation>
    </message>
    <message>
        <source>(remote)</source>
        <translation>（遠端）</translation>
    </message>
    <message>
        <source>once</source>
        <translation>一次</translation>
    </message>
    <message>
        <source>Periodic sending on or off</source>
        <translation>開啟或關閉週期發送</translation>
    </message>
    <message>
        <source>CAN identifier in hex (601, 601h or 0x601)</source>
        <translation>十六進位的 CAN 識別碼（601、601h 或 0x601）</translation>
    </message>
    <message>
        <source>Data bytes in hex (40 18 10 01)</source>
        <translation>十六進位的資料位元組（40 18 10 01）</translation>
    </message>
    <message>
        <source>Period in ms, to the microsecond (0.5 = 500 µs); 0 = sent once only</source>
        <translation>週期（ms），精確到微秒（0.5 = 500 µs）；0 = 只發送一次</translation>
    </message>
    <message>
        <source>Periodic</source>
        <translation>週期</translation>
    </message>
    <message>
        <source>ID</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>29-bit</source>
        <translation>29 位元</translation>
    </message>
    <message>
        <source>RTR</source>
        <translation>RTR</translation>
    </message>
    <message>
        <source>FD</source>
        <translation>FD</translation>
    </message>
    <message>
        <source>BRS</source>
        <translation>BRS</translation>
    </message>
    <message>
        <source>DLC</source>
        <translation>DLC</translation>
    </message>
    <message>
        <source>Data</source>
        <translation>資料</translation>
    </message>
    <message>
        <source>Every (ms)</source>
        <translation>每（ms）</translation>
    </message>
    <message>
        <source>Sent</source>
        <translation>已發送</translation>
    </message>
    <message>
        <source>Comment</source>
        <translation>備註</translation>
    </message>
    <message>
        <source>ID %1h needs 29 bits</source>
        <translation>ID %1h 需要 29 位元</translation>
    </message>
    <message>
        <source>CAN FD has no remote frames</source>
        <translation>CAN FD 沒有遠端封包</translation>
    </message>
    <message>
        <source>“%1” is not a CAN identifier (hex, up to 1FFFFFFFh)</source>
        <translation>「%1」不是 CAN 識別碼（十六進位，最大 1FFFFFFFh）</translation>
    </message>
    <message>
        <source>DLC must be a valid length of 0-%1 bytes</source>
        <translation>DLC 必須是 0-%1 位元組的有效長度</translation>
    </message>
    <message>
        <source>“%1” is not up to %2 hex bytes</source>
        <translation>「%1」不是最多 %2 個十六進位位元組</translation>
    </message>
    <message>
        <source>“%1” is not a period in ms (0 = once only, at least 0.1 ms)</source>
        <translation>「%1」不是以 ms 為單位的週期（0 = 只發送一次，至少 0.1 ms）</translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardFramesPane</name>
    <message>
        <source>Frames on the bus for this wizard</source>
        <translation>此精靈在匯流排上的封包</translation>
    </message>
</context>
<context>
    <name>coscope::gui::WizardGuard</name>
    <message>
        <source>No bus is connected, so nothing can be sent. Connect to the bus first; you can still prepare the steps and save them as a script.</source>
        <translation>未連線到任何匯流排，因此無法傳送。請先連線到匯流排；您仍可先準備步驟並另存為腳本。</translation>
    </message>
    <message>
        <source>The bus is open in listen-only mode: CoScope never transmits on it. Reconnect without listen-only to send these commands; you can still prepare the steps and save them as a script.</source>
        <translation>匯流排以僅監聽模式開啟：CoScope 不會在上面傳送。請取消僅監聽後重新連線才能送出這些指令；您仍可先準備步驟並另存為腳本。</translation>
    </message>
    <message>
        <source>The bus is still opening; sending is possible once it is open.</source>
        <translation>匯流排仍在開啟中；開啟後即可傳送。</translation>
    </message>
    <message>
        <source>The bus is not open (%1), so nothing can be sent.</source>
        <translation>匯流排未開啟（%1），因此無法傳送。</translation>
    </message>
    <message>
        <source>The bus was lost (%1); CoScope is reconnecting. Sending is possible again once it is back.</source>
        <translation>匯流排已中斷（%1）；CoScope 正在重新連線。恢復後即可再傳送。</translation>
    </message>
</context>
<context>
    <name>coscope::gui::Workspace</name>
    <message>
        <source>cannot create the folder %1</source>
        <translation>無法建立資料夾 %1</translation>
    </message>
    <message>
        <source>The capture is not journaled to disk (%1); it is kept in memory only</source>
        <translation>擷取內容未寫入磁碟日誌（%1）；僅保存在記憶體中</translation>
    </message>
    <message>
        <source>Capture stopped: cannot write the capture journal %1 (%2). The trace keeps the %L3 frames received.</source>
        <translation>擷取已停止：無法寫入擷取日誌 %1（%2）。追蹤中保留已收到的 %L3 個封包。</translation>
    </message>
    <message>
        <source>Bus lost: %1. Retrying with back-off; node states are unknown until their next heartbeat.</source>
        <translation>匯流排中斷：%1。正以逐步拉長的間隔重試；各節點的狀態在下一次心跳之前未知。</translation>
    </message>
    <message>
        <source>Bus back after %1 s: frames between are missing from the trace</source>
        <translation>匯流排在 %1 秒後恢復：中斷期間的封包不在追蹤中</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s) dropped (receive queue full), %1 in total</source>
        <translation>
            <numerusform>丟失 %n 個封包（接收佇列已滿），累計 %1 個</numerusform>
        </translation>
    </message>
    <message>
        <source>node %1 axis %2</source>
        <translation>節點 %1 軸 %2</translation>
    </message>
    <message>
        <source>node %1</source>
        <translation>節點 %1</translation>
    </message>
    <message>
        <source>Disable voltage (6040h = 0000h) sent to %1 before the bus closed, and seen on the bus</source>
        <translation>匯流排關閉前已向%1送出切斷電壓（Disable voltage，6040h = 0000h），並在匯流排上看到該訊框</translation>
    </message>
    <message>
        <source>%1 may still be enabled: its Disable voltage (6040h = 0000h) was not seen on the bus before it closed (%2). Check the drive.</source>
        <translation>%1 可能仍在致能狀態：匯流排關閉前未在匯流排上看到其切斷電壓（Disable voltage，6040h = 0000h）訊框（%2）。請檢查驅動器。</translation>
    </message>
    <message>
        <source>Node guarding lost: no answer within the node life time of %1 ms (guard time %2 ms × %3)</source>
        <translation>節點保護失去：在節點壽命時間 %1 ms 內無回應（守護時間 %2 ms × %3）</translation>
    </message>
    <message>
        <source>Heartbeat lost: none within the consumer time of %1 ms</source>
        <translation>心跳失去：在消費者時間 %1 ms 內未收到</translation>
    </message>
    <message>
        <source>Node guarding answers again</source>
        <translation>節點保護恢復回應</translation>
    </message>
    <message>
        <source>Heartbeat back</source>
        <translation>心跳恢復</translation>
    </message>
    <message>
        <source>%1: no CAN frame found (read as %2)</source>
        <translation>%1：找不到任何 CAN 封包（以 %2 格式讀取）</translation>
    </message>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
    <message>
        <source>%1: cannot read the file</source>
        <translation>%1：無法讀取檔案</translation>
    </message>
    <message>
        <source>%1: not a format CoScope reads (tried candump, Vector ASC and BLF, PEAK TRC, pcap/pcapng, CoScope CSV, SavvyCAN GVRET, BUSMASTER, IXXAT, Kvaser and ASAM MDF4); read as %2 by its name, no CAN frame was found</source>
        <translation>%1：不是 CoScope 可讀取的格式（已嘗試 candump、Vector ASC 與 BLF、PEAK TRC、pcap/pcapng、CoScope CSV、SavvyCAN GVRET、BUSMASTER、IXXAT、Kvaser 與 ASAM MDF4）；依檔名當作 %2 讀取，找不到 CAN 訊息</translation>
    </message>
</context>
<context>
    <name>coscope::gui::help::HelpWindow</name>
    <message>
        <source>CoScope guide</source>
        <translation>CoScope 使用指南</translation>
    </message>
    <message>
        <source>Back</source>
        <translation>上一頁</translation>
    </message>
    <message>
        <source>Forward</source>
        <translation>下一頁</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>目錄</translation>
    </message>
</context>
<context>
    <name>coscope::gui::help::ShortcutsDialog</name>
    <message>
        <source>Keyboard shortcuts</source>
        <translation>鍵盤快捷鍵</translation>
    </message>
    <message>
        <source>Keys</source>
        <translation>按鍵</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>動作</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>位置</translation>
    </message>
</context>
</TS>
