from http import HTTPStatus
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.segment_torque_out import SegmentTorqueOut
from ...models.segment_torque_request import SegmentTorqueRequest
from ...types import Response


def _get_kwargs(
    *,
    body: SegmentTorqueRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/segment/torque",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> ErrorOut | SegmentTorqueOut | None:
    if response.status_code == 200:
        response_200 = SegmentTorqueOut.from_dict(response.json())

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(
    *, client: AuthenticatedClient | Client, response: httpx.Response
) -> Response[ErrorOut | SegmentTorqueOut]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: SegmentTorqueRequest,
) -> Response[ErrorOut | SegmentTorqueOut]:
    """Torque M(q), its derivative and the energy of one segment

     Evaluates `Segment.torque`, `Segment.dtorque` and `Segment.energy` at the angles `q` (a list or
    `{start, stop, num}`, at most 10001 points), with the joint stiffness `K = E''(0)`, whether `M(q)`
    is monotonic over the physical range, and that range.

    Args:
        body (SegmentTorqueRequest): Torque curve `M(q)` of one segment.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | SegmentTorqueOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: SegmentTorqueRequest,
) -> ErrorOut | SegmentTorqueOut | None:
    """Torque M(q), its derivative and the energy of one segment

     Evaluates `Segment.torque`, `Segment.dtorque` and `Segment.energy` at the angles `q` (a list or
    `{start, stop, num}`, at most 10001 points), with the joint stiffness `K = E''(0)`, whether `M(q)`
    is monotonic over the physical range, and that range.

    Args:
        body (SegmentTorqueRequest): Torque curve `M(q)` of one segment.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | SegmentTorqueOut
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: SegmentTorqueRequest,
) -> Response[ErrorOut | SegmentTorqueOut]:
    """Torque M(q), its derivative and the energy of one segment

     Evaluates `Segment.torque`, `Segment.dtorque` and `Segment.energy` at the angles `q` (a list or
    `{start, stop, num}`, at most 10001 points), with the joint stiffness `K = E''(0)`, whether `M(q)`
    is monotonic over the physical range, and that range.

    Args:
        body (SegmentTorqueRequest): Torque curve `M(q)` of one segment.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | SegmentTorqueOut]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: SegmentTorqueRequest,
) -> ErrorOut | SegmentTorqueOut | None:
    """Torque M(q), its derivative and the energy of one segment

     Evaluates `Segment.torque`, `Segment.dtorque` and `Segment.energy` at the angles `q` (a list or
    `{start, stop, num}`, at most 10001 points), with the joint stiffness `K = E''(0)`, whether `M(q)`
    is monotonic over the physical range, and that range.

    Args:
        body (SegmentTorqueRequest): Torque curve `M(q)` of one segment.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | SegmentTorqueOut
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
